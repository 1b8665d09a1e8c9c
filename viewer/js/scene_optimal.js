// poinsot view: an optimal manoeuvre of `poinsot optimize`. The control torque u (body frame, N·m) as an arrow
// from the centre of mass (drawn in space, R u); its bounds in the body frame (|u_i| ≤ u_max,i: a box, or
// ‖u‖ ≤ ū: three great circles of the sphere), at the arrow's scale; the target attitude as a ghost of the
// body. The data are data.optimal (view_optimal.hpp): u per frame, control.csv's and costates.csv's rows,
// the switches and the target quaternion (null for a free final attitude). Pointing constraints (o.cones):
// each cone's edge on a sky sphere about the centre of mass (a circle at its half-angle about its axis, the
// axis drawn faint), each boresight's path R(t) b over the whole manoeuvre on the same sphere, and the
// boresight now as an arrow; keep-out in amber, keep-in in cyan. With reaction wheels (o.control_kind
// 'wheels') the arrow is the wheels' torque vector A u (body frame; the bus feels −A u), the box the per-wheel
// bounds (the bounds of A u for wheels on the body axes), and the chart the wheel torques u_k.
PV.OptimalScene = (function () {
  'use strict';
  var M = PV.math, D = PV.draw;
  var TORQUE = 0xd62728;

  function OptimalScene(ctx, body) {
    var data = ctx.data, o = data.optimal, wheels = o.control_kind === 'wheels';
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
    this.sky = 2.2 * body.length;
    this.cones = new THREE.Group();
    this.boresights = [];
    var sky = this.sky, frames = data.q.length / 4, scene = this;
    (o.cones || []).forEach(function (c) {
      var colour = c.kind === 'keep_out' ? 0xffbf00 : 0x17becf, a = c.direction_space;
      var e1 = M.cross(a, Math.abs(a[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0]);
      e1 = M.scale(e1, 1 / M.norm(e1));
      var e2 = M.cross(a, e1), edge = [];
      for (var i = 0; i < 96; i++) {
        var phi = 2 * Math.PI * i / 96;
        var r = M.add(M.scale(a, Math.cos(c.half_angle)),
                      M.scale(M.add(M.scale(e1, Math.cos(phi)), M.scale(e2, Math.sin(phi))), Math.sin(c.half_angle)));
        edge.push(M.scale(r, sky));
      }
      scene.cones.add(D.loop(edge, colour));
      scene.cones.add(D.tracedLine([0, 0, 0].concat(M.scale(a, sky)), colour, 0.4));
      var path = [];
      for (var f = 0; f < frames; f++) {
        var qf = [data.q[4 * f], data.q[4 * f + 1], data.q[4 * f + 2], data.q[4 * f + 3]];
        path = path.concat(M.scale(M.rotate(qf, c.boresight_body), sky));
      }
      scene.cones.add(D.tracedLine(path, colour, 0.8));
      var arrow = D.arrow(colour);
      ctx.scene.add(arrow);
      scene.boresights.push({ arrow: arrow, cone: c });
    });
    ctx.scene.add(this.cones);

    this.overlays = [
      { key: 'torque', label: wheels ? 'wheel torques A u (the bus feels \u2212A u)' : 'control torque u',
        objects: [this.arrow], on: true },
      { key: 'bounds', label: 'torque bounds', objects: [this.bounds], on: true }
    ];
    if (this.ghostPose) {
      this.overlays.push({ key: 'target', label: 'target attitude', objects: [this.ghostPose], on: true });
    }
    if (this.boresights.length) {
      this.overlays.push({ key: 'cones', label: 'pointing cones and boresight paths',
                           objects: [this.cones].concat(this.boresights.map(function (b) { return b.arrow; })),
                           on: true });
    }
    var bound = o.bound === 'norm' ? '\u2016u\u2016 \u2264 ' + m[0] + ' N\u00b7m'
                                   : '|u\u1d62| \u2264 (' + m.join(', ') + ') N\u00b7m' +
                                     (wheels ? ' per wheel' : '');
    this.legend = [
      ['#d62728', (wheels ? 'wheel torques A u' : 'torque u') + ', N\u00b7m (1 m = ' + (1 / s).toPrecision(3) +
                  ' N\u00b7m); bounds ' + bound],
      ['#7f7f7f', o.target ? 'target attitude' : 'free final attitude (detumbling)'],
      ['#ffffff', o.objective + ': ' + o.status]
    ];
    if (this.boresights.length) {
      this.legend.push(['#ffbf00', 'keep-out cones (edge, axis) and boresight paths'],
                       ['#17becf', 'keep-in cones (edge, axis) and boresight paths']);
    }
  }

  OptimalScene.prototype.update = function (time) {
    var u = this.ctx.track.value('u', time);
    this.u = u;
    this.arrow.set([0, 0, 0], M.scale(M.rotate(this.body.q, u), this.scale));
    if (this.ghost) this.ghost.userData.show(this.body.shapeShown());
    var q = this.body.q, sky = this.sky;
    this.boresights.forEach(function (b) { b.arrow.set([0, 0, 0], M.scale(M.rotate(q, b.cone.boresight_body), sky)); });
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
      target: g ? [g.w, g.x, g.y, g.z] : null,
      // Each boresight now (space frame, unit, from its arrow) and its angle to its cone's axis (rad).
      boresights: this.boresights.map(function (b) {
        var v = new THREE.Vector3(0, 1, 0).applyQuaternion(b.arrow.quaternion), a = b.cone.direction_space;
        return { direction: [v.x, v.y, v.z],
                 angle: Math.acos(Math.max(-1, Math.min(1, v.x * a[0] + v.y * a[1] + v.z * a[2]))) };
      })
    };
  };

  // The chart's views: the control (control.csv, exact between its rows, switches marked), the switching
  // functions (costates.csv), ω and, with pointing constraints, each boresight's angle to its cone's axis
  // beside the limit.
  OptimalScene.prototype.chartViews = function (omegaSeries) {
    var o = this.optimal, c = ['#d62728', '#2ca02c', '#1f77b4'], wheels = o.control_kind === 'wheels';
    function series(t, flat, name) {  // wheels: u1, u2, u3 and σ1, σ2, σ3 (per wheel); else x, y, z
      return (wheels ? ['1', '2', '3'] : ['x', 'y', 'z']).map(function (axis, k) {
        var v = [];
        for (var i = 0; i < t.length; i++) v.push(flat[3 * i + k]);
        return { label: name + axis, color: c[k], t: t, values: v };
      });
    }
    var marks = o.switches.map(function (s) { return s.t; });
    var data = this.ctx.data, frames = data.q.length / 4, pointing = [];
    (o.cones || []).forEach(function (cone, i) {
      var colour = ['#ff7f0e', '#9467bd', '#8c564b', '#e377c2'][i % 4], angle = [], limit = [];
      for (var f = 0; f < frames; f++) {
        var qf = [data.q[4 * f], data.q[4 * f + 1], data.q[4 * f + 2], data.q[4 * f + 3]];
        var c = M.dot(M.rotate(qf, cone.boresight_body), cone.direction_space);
        angle.push(Math.acos(Math.max(-1, Math.min(1, c))) * 180 / Math.PI);
        limit.push(cone.half_angle * 180 / Math.PI);
      }
      var name = cone.kind.replace('_', '-') + ' ' + (cone.name || i + 1);
      pointing.push({ label: name, color: colour, values: angle },
                    { label: name + ' limit', color: '#7f7f7f', values: limit });
    });
    var views = [
      { key: 'control', label: wheels ? 'wheel torques u\u2096' : 'control u',
        yLabel: wheels ? 'u wheel (N\u00b7m)' : 'u body (N\u00b7m)', marks: marks,
        series: series(o.control.t, o.control.u, 'u') },
      { key: 'sigma', label: 'switching functions \u03c3',
        yLabel: wheels ? '\u03c3 = \u2212A\u1d40J\u1d66\u207b\u00b9p\u03c9' : '\u03c3 = J\u207b\u00b9p\u03c9',
        marks: marks,
        series: series(o.costates.t, o.costates.sigma, '\u03c3') },
      { key: 'omega', label: '\u03c9', yLabel: '\u03c9 body (rad/s)', marks: marks, series: omegaSeries }
    ];
    if (pointing.length) {
      views.push({ key: 'pointing', label: 'pointing angles', yLabel: 'boresight to cone axis (deg)', marks: marks,
                   series: pointing });
    }
    return views;
  };

  return OptimalScene;
})();
