// poinsot view: an optimal manoeuvre of `poinsot optimize`. The control torque u (body frame, N·m) as an arrow
// from the centre of mass (drawn in space, R u); its bounds in the body frame (|u_i| ≤ u_max,i: a box, or
// ‖u‖ ≤ ū: three great circles of the sphere), at the arrow's scale; the target attitude as a ghost of the
// body. The data are data.optimal (view_optimal.hpp): u per frame, control.csv's and costates.csv's rows,
// the switches and the target quaternion (null for a free final attitude).
PV.OptimalScene = (function () {
  'use strict';
  var M = PV.math, D = PV.draw;
  var TORQUE = 0xd62728;

  function OptimalScene(ctx, body) {
    var data = ctx.data, o = data.optimal;
    this.ctx = ctx; this.body = body; this.optimal = o;
    ctx.track.fields.u = { data: o.u, width: 3, kind: 'vec' };
    this.scale = 1.2 * body.length / o.torque_norm_limit;  // m per N·m: the largest torque allowed
    this.arrow = D.arrow(TORQUE);  // drawn over the body, which it starts inside
    [this.arrow.line, this.arrow.cone].forEach(function (part) {
      part.material.depthTest = false; part.renderOrder = 10;
    });
    ctx.scene.add(this.arrow);

    // The bounds turn with the body (they bound the body-frame torque).
    var s = this.scale, m = o.torque_max;
    var lines = new THREE.LineBasicMaterial({ color: TORQUE, transparent: true, opacity: 0.5, depthTest: false });
    if (o.bound === 'norm') {
      this.bounds = new THREE.Group();
      for (var k = 0; k < 3; k++) {
        var circle = [];
        for (var i = 0; i < 96; i++) {
          var a = 2 * Math.PI * i / 96, p = [0, 0, 0];
          p[(k + 1) % 3] = m[0] * s * Math.cos(a); p[(k + 2) % 3] = m[0] * s * Math.sin(a);
          circle.push(p);
        }
        var loop = D.loop(circle, TORQUE);
        loop.material.depthTest = false;
        this.bounds.add(loop);
      }
    } else {
      this.bounds = new THREE.LineSegments(
          new THREE.EdgesGeometry(new THREE.BoxGeometry(2 * m[0] * s, 2 * m[1] * s, 2 * m[2] * s)), lines);
    }
    this.bounds.userData.halfExtents = [m[0] * s, m[1] * s, m[2] * s];
    body.group.add(this.bounds);

    // The target attitude: the body's shapes, faint, turned by R_f about the same centre.
    this.ghost = null;
    if (o.target) {
      this.ghost = D.bodyShapes(data.body.shapes, 0x7f7f7f, 0.02 * body.length);
      var material = this.ghost.userData.box.material;
      material.opacity = 0.25; material.depthWrite = false;
      this.ghost.userData.show(body.shapeShown());
      var q = o.target;
      this.ghostPose = new THREE.Group();
      this.ghostPose.quaternion.set(q[1], q[2], q[3], q[0]);
      this.ghostPose.add(this.ghost);
      ctx.scene.add(this.ghostPose);
    }
    this.overlays = [
      { key: 'torque', label: 'control torque u', objects: [this.arrow], on: true },
      { key: 'bounds', label: 'torque bounds', objects: [this.bounds], on: true }
    ];
    if (this.ghostPose) {
      this.overlays.push({ key: 'target', label: 'target attitude', objects: [this.ghostPose], on: true });
    }
    var bound = o.bound === 'norm' ? '\u2016u\u2016 \u2264 ' + m[0] + ' N\u00b7m'
                                   : '|u\u1d62| \u2264 (' + m.join(', ') + ') N\u00b7m';
    this.legend = [
      ['#d62728', 'torque u, N\u00b7m (1 m = ' + (1 / s).toPrecision(3) + ' N\u00b7m); bounds ' + bound],
      ['#7f7f7f', o.target ? 'target attitude' : 'free final attitude (detumbling)'],
      ['#ffffff', o.objective + ': ' + o.status]
    ];
  }

  OptimalScene.prototype.update = function (time) {
    var u = this.ctx.track.value('u', time);
    this.u = u;
    this.arrow.set([0, 0, 0], M.scale(M.rotate(this.body.q, u), this.scale));
    if (this.ghost) this.ghost.userData.show(this.body.shapeShown());
  };

  // What is drawn (for tests): the torque (N·m, space frame, from the arrow), the bounds' half-extents
  // (N·m, body frame) and the ghost's quaternion [w, x, y, z].
  OptimalScene.prototype.probe = function () {
    var a = this.arrow, d = new THREE.Vector3(0, 1, 0).applyQuaternion(a.quaternion), s = this.scale;
    var g = this.ghostPose ? this.ghostPose.quaternion : null;
    return {
      torque: [d.x * a.userData.length / s, d.y * a.userData.length / s, d.z * a.userData.length / s],
      bounds: this.bounds.userData.halfExtents.map(function (h) { return h / s; }),
      boundsFollowBody: this.bounds.parent === this.body.group,
      target: g ? [g.w, g.x, g.y, g.z] : null
    };
  };

  // The chart's views: the control (control.csv, exact between its rows, switches marked), the switching
  // functions (costates.csv) and ω.
  OptimalScene.prototype.chartViews = function (omegaSeries) {
    var o = this.optimal, c = ['#d62728', '#2ca02c', '#1f77b4'];
    function series(t, flat, name) {
      return ['x', 'y', 'z'].map(function (axis, k) {
        var v = [];
        for (var i = 0; i < t.length; i++) v.push(flat[3 * i + k]);
        return { label: name + axis, color: c[k], t: t, values: v };
      });
    }
    var marks = o.switches.map(function (s) { return s.t; });
    return [
      { key: 'control', label: 'control u', yLabel: 'u body (N\u00b7m)', marks: marks,
        series: series(o.control.t, o.control.u, 'u') },
      { key: 'sigma', label: 'switching functions \u03c3', yLabel: '\u03c3 = J\u207b\u00b9p\u03c9', marks: marks,
        series: series(o.costates.t, o.costates.sigma, '\u03c3') },
      { key: 'omega', label: '\u03c9', yLabel: '\u03c9 body (rad/s)', marks: marks, series: omegaSeries }
    ];
  };

  return OptimalScene;
})();
