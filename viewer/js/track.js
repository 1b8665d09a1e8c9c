// poinsot view: the run's frames and the state at any time between them. A frame is a row of trajectory.csv;
// between frames the orientation is interpolated by slerp and the vectors linearly. At a frame's time the
// state is that frame's numbers exactly.
PV.Track = (function () {
  'use strict';
  var M = PV.math;

  // t: frame times (s, increasing); fields: name -> {data: flat array, width: numbers per frame, kind:
  // 'quat' | 'vec'}.
  function Track(t, fields) {
    this.t = t;
    this.n = t.length;
    this.fields = fields;
  }

  // The frame i with t[i] <= time < t[i+1] (clamped) and the fraction u in [0, 1] towards i + 1.
  Track.prototype.locate = function (time) {
    var t = this.t, n = this.n;
    if (time <= t[0]) return { i: 0, u: 0 };
    if (time >= t[n - 1]) return { i: n - 1, u: 0 };
    var lo = 0, hi = n - 1;
    while (hi - lo > 1) {
      var mid = (lo + hi) >> 1;
      if (t[mid] <= time) lo = mid; else hi = mid;
    }
    return { i: lo, u: (time - t[lo]) / (t[lo + 1] - t[lo]) };
  };

  // The value of a field at frame i (array of its width).
  Track.prototype.at = function (name, i) {
    var f = this.fields[name];
    return f.data.slice(i * f.width, (i + 1) * f.width);
  };

  // The value of a field at a time.
  Track.prototype.value = function (name, time) {
    var p = this.locate(time);
    var a = this.at(name, p.i);
    if (p.u === 0) return a;
    var b = this.at(name, p.i + 1);
    if (this.fields[name].kind === 'quat') return M.slerp(a, b, p.u);
    var out = [];
    for (var k = 0; k < a.length; k++) out.push(a[k] + p.u * (b[k] - a[k]));
    return out;
  };

  return Track;
})();
