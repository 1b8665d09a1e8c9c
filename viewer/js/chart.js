// poinsot view: a small chart (canvas 2D) of the frames' series against time with a cursor at the current
// time; a click moves the time there.
PV.Chart = (function () {
  'use strict';

  // series: [{label, color, values (one per frame, or one per time of its own `t`)}]; yLabel names the
  // quantity and its unit; marks: times (s) drawn as dashed vertical lines (e.g. switches).
  function Chart(canvas, t, series, yLabel, onSeek, marks) {
    this.canvas = canvas; this.t = t; this.series = series; this.yLabel = yLabel; this.marks = marks || [];
    var lo = Infinity, hi = -Infinity;
    series.forEach(function (s) {
      s.values.forEach(function (v) { if (isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); } });
    });
    if (!(hi > lo)) { lo -= 1; hi += 1; }
    var pad = 0.05 * (hi - lo);
    this.lo = lo - pad; this.hi = hi + pad;
    this.box = { left: 66, right: canvas.width - 8, top: 8, bottom: canvas.height - 30 };
    var self = this;
    canvas.addEventListener('click', function (e) {
      var r = canvas.getBoundingClientRect();
      var x = (e.clientX - r.left) * canvas.width / r.width;
      var u = (x - self.box.left) / (self.box.right - self.box.left);
      onSeek(t[0] + Math.min(1, Math.max(0, u)) * (t[t.length - 1] - t[0]));
    });
  }

  // A short number for an axis: 3 significant digits, in exponent form when small or large.
  function label(v) {
    var a = Math.abs(v);
    return a !== 0 && (a < 1e-2 || a >= 1e4) ? v.toExponential(2) : v.toPrecision(3);
  }

  Chart.prototype.x = function (time) {
    var t = this.t;
    return this.box.left + (time - t[0]) / (t[t.length - 1] - t[0]) * (this.box.right - this.box.left);
  };
  Chart.prototype.y = function (v) {
    return this.box.bottom - (v - this.lo) / (this.hi - this.lo) * (this.box.bottom - this.box.top);
  };

  Chart.prototype.draw = function (time) {
    var c = this.canvas.getContext('2d'), b = this.box, self = this, t = this.t;
    c.clearRect(0, 0, this.canvas.width, this.canvas.height);
    c.strokeStyle = '#888'; c.lineWidth = 1;
    c.strokeRect(b.left, b.top, b.right - b.left, b.bottom - b.top);
    c.fillStyle = '#222'; c.font = '11px sans-serif';
    c.textAlign = 'right';
    c.fillText(label(this.hi), b.left - 3, b.top + 9);
    c.fillText(label(this.lo), b.left - 3, b.bottom);
    c.textAlign = 'center';
    c.fillText('t (s)', (b.left + b.right) / 2, this.canvas.height - 4);
    c.fillText(t[0].toPrecision(3), b.left, b.bottom + 12);
    c.fillText(t[t.length - 1].toPrecision(4), b.right - 10, b.bottom + 12);
    c.save(); c.translate(10, (b.top + b.bottom) / 2); c.rotate(-Math.PI / 2);
    c.fillText(this.yLabel, 0, 0); c.restore();
    c.strokeStyle = '#7f7f7f'; c.setLineDash([3, 3]);
    this.marks.forEach(function (m) {
      c.beginPath(); c.moveTo(self.x(m), b.top); c.lineTo(self.x(m), b.bottom); c.stroke();
    });
    c.setLineDash([]);
    this.series.forEach(function (s, k) {
      var st = s.t || t, step = Math.max(1, Math.floor(st.length / 1000));
      c.strokeStyle = s.color; c.beginPath();
      for (var i = 0; i < st.length; i += step) {
        var X = self.x(st[i]), Y = self.y(s.values[i]);
        if (i === 0) c.moveTo(X, Y); else c.lineTo(X, Y);
      }
      c.stroke();
      c.fillStyle = s.color; c.textAlign = 'left';
      c.fillText(s.label, b.left + 6 + 44 * k, b.top + 12);
    });
    c.strokeStyle = '#000'; c.beginPath();
    c.moveTo(this.x(time), b.top); c.lineTo(this.x(time), b.bottom); c.stroke();
  };

  return Chart;
})();
