// poinsot view: a multibody file. Every body as the uniform box (or ellipsoid) with its inertia, placed at its
// centre of mass x and turned by its R; every joint as a ball at its point with links to the centres of mass
// of the bodies it joins (a fixed square marks a joint to the world); the paths of the centres of mass.
PV.MultibodyScene = (function () {
  'use strict';
  var M = PV.math, D = PV.draw;
  var palette = [0xc8a165, 0x8fbcd4, 0xb5cf6b, 0xe6a0c4, 0xd6a756, 0x9e9ac8];

  function MultibodyScene(ctx) {
    var data = ctx.data, track = ctx.track;
    this.ctx = ctx;
    // The scene's length scale: the spread of the centres of mass over the run, or the largest body.
    var lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    data.bodies.forEach(function (b, k) {
      for (var i = 0; i < track.n; i++) {
        var x = track.at('x' + k, i);
        for (var c = 0; c < 3; c++) { lo[c] = Math.min(lo[c], x[c]); hi[c] = Math.max(hi[c], x[c]); }
      }
    });
    var size = 0;  // the largest body
    data.bodies.forEach(function (b) {
      if (b.shapes) size = Math.max(size, Math.max.apply(null, b.shapes.box_half_extents));
    });
    var span = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 2 * size) || 1;
    ctx.length = span / 2;
    ctx.center = M.scale(M.add(lo, hi), 0.5);
    var marker = 0.02 * span;

    this.bodies = data.bodies.map(function (b, k) {
      var group = new THREE.Group();
      var shapes = b.shapes || { box_half_extents: [marker, marker, marker],
                                 ellipsoid_semi_axes: [marker, marker, marker],
                                 axes: [[1, 0, 0], [0, 1, 0], [0, 0, 1]], surface: null };
      var mesh = D.bodyShapes(shapes, palette[k % palette.length], 0.25 * marker);
      group.add(mesh);
      ctx.scene.add(group);
      return { group: group, shapes: mesh };
    });
    this.anySurface = data.bodies.some(function (b) { return b.shapes && b.shapes.surface; });
    this.showShape(this.anySurface ? 'surface' : 'box');
    this.paths = new THREE.Group();
    data.bodies.forEach(function (b, k) {
      var pts = [];
      for (var i = 0; i < track.n; i++) { var x = track.at('x' + k, i); pts.push(x[0], x[1], x[2]); }
      var line = D.tracedLine(pts, palette[k % palette.length]);
      this.paths.add(line);
    }, this);
    ctx.scene.add(this.paths);

    this.joints = data.joints.map(function (j) {
      var ball = new THREE.Mesh(new THREE.SphereGeometry(marker, 12, 8),
                                new THREE.MeshBasicMaterial({ color: j.type === 'hinge' ? 0x1f77b4 : 0x222222 }));
      var links = D.tracedLine([0, 0, 0, 0, 0, 0, 0, 0, 0], 0x444444);
      ctx.scene.add(ball); ctx.scene.add(links);
      if (j.body_b < 0) {
        var anchor = new THREE.Mesh(new THREE.BoxGeometry(2 * marker, 2 * marker, 2 * marker),
                                    new THREE.MeshBasicMaterial({ color: 0x000000 }));
        anchor.position.copy(D.v3(j.point_b));
        ctx.scene.add(anchor);
      }
      return { spec: j, ball: ball, links: links };
    });
    // Gravity: an arrow beside the scene, a quarter of its span long.
    this.gravityArrow = D.arrow(0x2ca02c);
    var g = data.gravity || [0, 0, 0], gn = M.norm(g);
    if (gn > 0) {
      var gdir = M.scale(g, 1 / gn);
      var side = M.norm(M.cross(gdir, [1, 0, 0])) > 0.5 ? [1, 0, 0] : [0, 1, 0];
      this.gravityArrow.set(M.add(ctx.center, M.add(M.scale(side, -0.7 * span), M.scale(gdir, -0.125 * span))),
                            M.scale(gdir, 0.25 * span));
      ctx.scene.add(this.gravityArrow);
    }
    var jointObjects = [];
    this.joints.forEach(function (j) { jointObjects.push(j.ball, j.links); });
    this.overlays = [
      { key: 'shape', label: 'bodies', objects: this.bodies.map(function (b) { return b.shapes; }), on: true },
      { key: 'joints', label: 'joints', objects: jointObjects, on: true },
      { key: 'paths', label: 'paths of the centres of mass', objects: [this.paths], on: true },
      { key: 'gravity', label: 'gravity', objects: [this.gravityArrow], on: gn > 0 }
    ];
    this.legend = data.bodies.map(function (b, k) {
      return ['#' + palette[k % palette.length].toString(16), b.name + (b.mass ? ' (' + b.mass + ' kg)' : '')];
    });
    if (!data.model_from_scenario) this.legend.push(['#ffffff', 'scenario file not found: bodies drawn as markers']);
    this.legend.push(['#222222', 'ball joint'], ['#1f77b4', 'hinge joint']);
    if (gn > 0) this.legend.push(['#2ca02c', 'gravity g = ' + gn.toPrecision(3) + ' m/s\u00b2']);
  }

  // Shows the next of: the scenario's surfaces (where given; the box elsewhere), the boxes, the ellipsoids.
  MultibodyScene.prototype.toggleShape = function () {
    var order = ['surface', 'box', 'ellipsoid'];
    var next = order[(order.indexOf(this.shown) + 1) % 3];
    if (next === 'surface' && !this.anySurface) next = 'box';
    this.showShape(next);
    return next;
  };

  MultibodyScene.prototype.showShape = function (name) {
    this.shown = name;
    this.bodies.forEach(function (b) {
      var u = b.shapes.userData;
      u.show(u.order.indexOf(name) >= 0 ? name : 'box');
    });
  };

  MultibodyScene.prototype.shapeShown = function () { return this.shown; };

  MultibodyScene.prototype.update = function (time, where) {
    var track = this.ctx.track, states = [];
    this.bodies.forEach(function (b, k) {
      var x = track.value('x' + k, time), q = track.value('q' + k, time);
      b.group.position.set(x[0], x[1], x[2]);
      b.group.quaternion.set(q[1], q[2], q[3], q[0]);
      states.push({ x: x, q: q });
    });
    this.joints.forEach(function (j) {
      var a = states[j.spec.body_a];
      var p = M.add(a.x, M.rotate(a.q, j.spec.point_a));
      j.ball.position.set(p[0], p[1], p[2]);
      // The same joint point seen from body b (or the world): apart from p by the joint's gap only.
      var b = j.spec.body_b >= 0 ? states[j.spec.body_b] : null;
      j.fromB = b ? M.add(b.x, M.rotate(b.q, j.spec.point_b)) : j.spec.point_b;
      j.gap = M.norm(M.sub(p, j.fromB));
      var other = b ? b.x : j.spec.point_b;
      var pos = j.links.geometry.attributes.position;
      pos.setXYZ(0, a.x[0], a.x[1], a.x[2]); pos.setXYZ(1, p[0], p[1], p[2]);
      pos.setXYZ(2, other[0], other[1], other[2]);
      pos.needsUpdate = true;
    });
    this.paths.children.forEach(function (l) { l.showUpTo(where.i + 1); });
  };

  // The largest distance (m) between a joint's point placed from body a and from body b, as drawn now.
  MultibodyScene.prototype.jointGap = function () {
    return this.joints.reduce(function (g, j) { return Math.max(g, j.gap); }, 0);
  };

  return MultibodyScene;
})();
