// poinsot view: tops and the gyroscope. The pivot (the rotation point, at the origin), gravity as an arrow,
// the symmetry (figure) axis from the pivot, and its tip traced on a sphere about the pivot: nutation loops
// and precession. Also for a free symmetric top, whose figure axis turns about L.
PV.TopScene = (function () {
  'use strict';
  var M = PV.math, D = PV.draw;

  function TopScene(ctx, bodyScene) {
    var data = ctx.data, top = data.top, track = ctx.track;
    this.ctx = ctx;
    this.bodyScene = bodyScene;
    var radius = 1.3 * ctx.length;
    this.radius = radius;
    var axis = top.axis_body;
    var tip = M.scale(axis, radius);

    this.figureAxis = D.tracedLine([0, 0, 0, tip[0], tip[1], tip[2]], 0x000000);
    bodyScene.group.add(this.figureAxis);
    this.sphere = new THREE.Mesh(new THREE.SphereGeometry(radius, 36, 18), new THREE.MeshBasicMaterial(
        { color: 0x888888, wireframe: true, transparent: true, opacity: 0.15 }));
    ctx.scene.add(this.sphere);
    this.pivot = new THREE.Mesh(new THREE.SphereGeometry(0.05 * ctx.length, 16, 8),
                                new THREE.MeshBasicMaterial({ color: 0x000000 }));
    this.pivot.visible = data.body.has_pivot;
    ctx.scene.add(this.pivot);

    var pts = [];
    for (var i = 0; i < track.n; i++) {
      var p = M.rotate(track.at('q', i), tip);
      pts.push(p[0], p[1], p[2]);
    }
    this.tipTrace = D.tracedLine(pts, 0xe7298a);
    ctx.scene.add(this.tipTrace);

    var g = data.gravity, gn = M.norm(g);
    this.gravityArrow = D.arrow(0x2ca02c);
    if (gn > 0) {
      var gdir = M.scale(g, 1 / gn);
      var side = M.norm(M.cross(gdir, [1, 0, 0])) > 0.5 ? [1, 0, 0] : [0, 1, 0];
      this.gravityArrow.set(M.add(M.scale(side, -1.25 * radius), M.scale(gdir, -0.4 * radius)),
                            M.scale(gdir, 0.8 * radius));
    } else {
      this.gravityArrow.userData.enabled = false;
      this.gravityArrow.visible = false;
    }
    ctx.scene.add(this.gravityArrow);

    this.overlays = [
      { key: 'figure', label: 'figure axis', objects: [this.figureAxis], on: true },
      { key: 'sphere', label: 'sphere of the tip', objects: [this.sphere], on: true },
      { key: 'tip', label: 'tip trace', objects: [this.tipTrace], on: true },
      { key: 'gravity', label: 'gravity', objects: [this.gravityArrow, this.pivot], on: gn > 0 || data.body.has_pivot }
    ];
    this.legend = [['#e7298a', 'tip of the figure axis (' + top.kind + ')']];
    if (gn > 0) this.legend.push(['#2ca02c', 'gravity g = ' + gn.toPrecision(3) + ' m/s\u00b2']);
  }

  TopScene.prototype.update = function (time, where) { this.tipTrace.showUpTo(where.i + 1); };

  return TopScene;
})();
