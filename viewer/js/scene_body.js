// poinsot view: one rigid body. Its uniform box (or ellipsoid, a toggle) with the body's inertia about the
// centre of mass, its principal axes (red, green, blue: ascending moments), omega as an arrow from the rotation
// point (space frame, R omega), the angular momentum L (space frame) and the trail of a body point (a corner of
// the box). The body group's origin is the rotation point (the pivot of a top, else the centre of mass).
PV.BodyScene = (function () {
  'use strict';
  var M = PV.math, D = PV.draw;

  function BodyScene(ctx) {
    var data = ctx.data, body = data.body, track = ctx.track;
    this.ctx = ctx;
    var h = body.shapes.box_half_extents;
    var hmax = Math.max(h[0], h[1], h[2]);
    this.length = hmax + M.norm(body.pivot_to_com);  // the scene's length scale (m)
    ctx.length = this.length;

    this.group = new THREE.Group();  // moves with the body: position = rotation point, quaternion = R
    ctx.scene.add(this.group);
    var com = new THREE.Group();
    com.position.copy(D.v3(body.pivot_to_com));
    this.group.add(com);
    this.shapes = D.bodyShapes(body.shapes, 0xc8a165, 0.02 * hmax);
    com.add(this.shapes);
    this.axes = D.principalAxes(body.shapes.axes, [1.35 * hmax, 1.35 * hmax, 1.35 * hmax]);
    com.add(this.axes);

    // omega's scale (m per rad/s): the Poinsot scene sets it so that omega's tip is the contact point.
    var wmax = 0, lmax = 0;
    for (var i = 0; i < track.n; i++) {
      wmax = Math.max(wmax, M.norm(track.at('omega_body', i)));
      lmax = Math.max(lmax, M.norm(track.at('L_space', i)));
    }
    this.omegaScale = wmax > 0 ? 1.6 * this.length / wmax : 1;
    this.momentumScale = lmax > 0 ? 1.8 * this.length / lmax : 1;
    this.omegaArrow = D.arrow(0xff7f0e);
    this.momentumArrow = D.arrow(0x9467bd);
    ctx.scene.add(this.omegaArrow); ctx.scene.add(this.momentumArrow);

    // The trail of a corner of the box, every frame precomputed (space frame, m).
    var corner = M.add(body.pivot_to_com, M.matVec(body.shapes.axes, h));
    var pts = [];
    for (i = 0; i < track.n; i++) {
      var p = M.rotate(track.at('q', i), corner);
      pts.push(p[0], p[1], p[2]);
    }
    this.trail = D.tracedLine(pts, 0x555555, 0.7);
    ctx.scene.add(this.trail);

    this.overlays = [
      { key: 'shape', label: 'body (' + (body.shapes.surface ? 'shape' : 'box') + ')', objects: [this.shapes],
        on: true },
      { key: 'axes', label: 'principal axes', objects: [this.axes], on: true },
      { key: 'omega', label: '\u03c9 arrow', objects: [this.omegaArrow], on: true },
      { key: 'L', label: 'L arrow', objects: [this.momentumArrow], on: true },
      { key: 'trail', label: 'trail of a corner', objects: [this.trail], on: !data.top && data.torque !== 'none' }
    ];
    this.legend = [
      ['#d62728', 'principal axis 1 (smallest moment)'], ['#2ca02c', 'principal axis 2'],
      ['#1f77b4', 'principal axis 3 (largest moment)'],
      ['#ff7f0e', '\u03c9, rad/s (scaled)'], ['#9467bd', 'L, kg\u00b7m\u00b2/s (scaled)'],
      ['#555555', 'trail of a body point']
    ];
    var n = body.shapes.surface_triangles;
    if (n) {
      this.legend.push(['#c8a165', body.shapes.surface
                                       ? 'the scenario\'s shape (' + n + ' triangles); b: box, ellipsoid'
                                       : 'a mesh of ' + n + ' triangles, too many to draw: its box']);
    }
  }

  // Shows the next of the scenario's surface (when it has one), the box and the ellipsoid of the same inertia.
  BodyScene.prototype.toggleShape = function () { return this.shapes.userData.next(); };

  BodyScene.prototype.shapeShown = function () { return this.shapes.userData.shown; };

  BodyScene.prototype.update = function (time, where) {
    var track = this.ctx.track;
    var q = track.value('q', time);
    this.q = q;
    this.group.quaternion.set(q[1], q[2], q[3], q[0]);
    var w = track.value('omega_body', time);
    this.omega = w;
    this.omegaArrow.set([0, 0, 0], M.scale(M.rotate(q, w), this.omegaScale));
    this.momentumArrow.set([0, 0, 0], M.scale(track.value('L_space', time), this.momentumScale));
    this.trail.showUpTo(where.i + 1);
  };

  return BodyScene;
})();
