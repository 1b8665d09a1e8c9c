// poinsot view: Poinsot's construction for a torque-free body. The inertia ellipsoid x^T J x = 2T (x in rad/s,
// body frame, J about the rotation point) drawn at s metres per rad/s and carried by the body, rolls without
// slipping on the invariable plane: normal to the fixed L, at the distance 2T/|L| (rad/s) from the centre.
// The point of contact is where the ellipsoid's normal J x is parallel to L, x = J^-1 L_b sqrt(2T / L_b^T J^-1
// L_b) with L_b = R^T L (computed so, not copied from omega): it is the tip of omega, which the page's tests
// check. The polhode (contact point in the body) and the herpolhode (in the plane) are traced as time goes;
// the separatrix (L^2 = 2T I2) is drawn on the ellipsoid for an asymmetric body.
PV.PoinsotScene = (function () {
  'use strict';
  var M = PV.math, D = PV.draw;

  function PoinsotScene(ctx, bodyScene) {
    var data = ctx.data, body = data.body, track = ctx.track;
    this.ctx = ctx;
    this.bodyScene = bodyScene;
    this.I = body.principal_moments;   // kg m^2, about the rotation point, ascending
    this.axes = body.inertia_axes;     // columns, body frame
    this.twoT = 2 * data.initial.energy;  // J (torque-free: no potential)
    this.L = data.initial.L_space;        // kg m^2/s, space frame, fixed
    this.Lnorm = M.norm(this.L);
    this.normal = M.scale(this.L, 1 / this.Lnorm);
    this.distance = this.twoT / this.Lnorm;  // rad/s
    var semi = this.I.map(function (I) { return Math.sqrt(this.twoT / I); }, this);
    this.semiAxes = semi;
    this.scale = 1.5 * ctx.length / Math.max(semi[0], semi[1], semi[2]);  // m per rad/s
    bodyScene.omegaScale = this.scale;  // omega's tip is then the contact point
    var s = this.scale;

    this.ellipsoid = new THREE.Mesh(new THREE.SphereGeometry(1, 48, 24), new THREE.MeshPhongMaterial(
        { color: 0x6baed6, transparent: true, opacity: 0.35, depthWrite: false }));
    this.ellipsoid.scale.set(s * semi[0], s * semi[1], s * semi[2]);
    this.ellipsoid.quaternion.copy(D.basis(this.axes));
    bodyScene.group.add(this.ellipsoid);

    // Polhode (body frame) and herpolhode (space frame) of every frame, drawn up to the current one.
    var pol = [], her = [];
    this.herpolhode = [];
    for (var i = 0; i < track.n; i++) {
      var q = track.at('q', i);
      var x = this.contactBody(q);
      pol.push(s * x[0], s * x[1], s * x[2]);
      var p = M.scale(M.rotate(q, x), s);
      her.push(p[0], p[1], p[2]);
      this.herpolhode.push(p);
    }
    this.polhode = D.tracedLine(pol, 0xd62728);
    bodyScene.group.add(this.polhode);
    this.herpolhodeLine = D.tracedLine(her, 0x08519c);
    ctx.scene.add(this.herpolhodeLine);

    // The invariable plane: a disc normal to L through the foot point s d n.
    var foot = M.scale(this.normal, s * this.distance);
    var rmax = 0;
    this.herpolhode.forEach(function (p) { rmax = Math.max(rmax, M.norm(M.sub(p, foot))); });
    this.plane = new THREE.Mesh(new THREE.CircleGeometry(Math.max(1.3 * rmax, 0.6 * ctx.length), 64),
        new THREE.MeshBasicMaterial({ color: 0x999999, transparent: true, opacity: 0.3, side: THREE.DoubleSide,
                                      depthWrite: false }));
    this.plane.position.copy(D.v3(foot));
    this.plane.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), D.v3(this.normal));
    ctx.scene.add(this.plane);

    this.contact = new THREE.Mesh(new THREE.SphereGeometry(0.03 * ctx.length, 16, 8),
                                  new THREE.MeshBasicMaterial({ color: 0x000000 }));
    ctx.scene.add(this.contact);

    this.separatrix = new THREE.Group();
    this.separatrixLoops().forEach(function (loop) {
      this.separatrix.add(D.loop(loop.map(function (x) { return M.scale(x, s); }), 0x333333));
    }, this);
    bodyScene.group.add(this.separatrix);

    this.overlays = [
      { key: 'ellipsoid', label: 'inertia ellipsoid', objects: [this.ellipsoid], on: true },
      { key: 'plane', label: 'invariable plane', objects: [this.plane], on: true },
      { key: 'polhode', label: 'polhode', objects: [this.polhode], on: true },
      { key: 'herpolhode', label: 'herpolhode', objects: [this.herpolhodeLine], on: true },
      { key: 'separatrix', label: 'separatrix', objects: [this.separatrix], on: true },
      { key: 'contact', label: 'contact point', objects: [this.contact], on: true }
    ];
    this.legend = [
      ['#6baed6', 'inertia ellipsoid x\u1d40Jx = 2T (x in rad/s, ' + s.toPrecision(3) + ' m per rad/s)'],
      ['#999999', 'invariable plane, normal to L, at 2T/|L| = ' + this.distance.toPrecision(4) + ' rad/s'],
      ['#d62728', 'polhode (on the ellipsoid)'], ['#08519c', 'herpolhode (on the plane)'],
      ['#333333', 'separatrix (L\u00b2 = 2T I\u2082)']
    ];
  }

  // The contact point in the body frame (rad/s): the point of the ellipsoid whose normal is L_b = R^T L.
  PoinsotScene.prototype.contactBody = function (q) {
    var Lb = M.rotateInverse(q, this.L);
    var y = [0, 1, 2].map(function (k) { return M.dot(M.column(this.axes, k), Lb) / this.I[k]; }, this);
    var c = Math.sqrt(this.twoT / (y[0] * y[0] * this.I[0] + y[1] * y[1] * this.I[1] + y[2] * y[2] * this.I[2]));
    return M.scale(M.matVec(this.axes, y), c);
  };

  // Two ellipses (arrays of body-frame points, rad/s) where the separatrix polhode L^2 = 2T I2 meets the
  // ellipsoid: in principal coordinates the planes I1 (I2 - I1) x1^2 = I3 (I3 - I2) x3^2; none when two
  // moments are equal (no unstable axis).
  PoinsotScene.prototype.separatrixLoops = function () {
    var I = this.I, loops = [];
    if (!(I[1] - I[0] > 1e-9 * I[2] && I[2] - I[1] > 1e-9 * I[2])) return loops;
    var c = Math.sqrt(I[0] * (I[1] - I[0]) / (I[2] * (I[2] - I[1])));
    [c, -c].forEach(function (cc) {
      var n = Math.sqrt(1 + cc * cc), u = [1 / n, 0, cc / n];
      var a = Math.sqrt(this.twoT / (I[0] * u[0] * u[0] + I[2] * u[2] * u[2])), b = Math.sqrt(this.twoT / I[1]);
      var pts = [];
      for (var k = 0; k < 128; k++) {
        var phi = 2 * Math.PI * k / 128;
        var p = [a * Math.cos(phi) * u[0], b * Math.sin(phi), a * Math.cos(phi) * u[2]];
        pts.push(M.matVec(this.axes, p));
      }
      loops.push(pts);
    }, this);
    return loops;
  };

  PoinsotScene.prototype.update = function (time, where) {
    var q = this.bodyScene.q;
    var x = M.scale(M.rotate(q, this.contactBody(q)), this.scale);
    this.contact.position.set(x[0], x[1], x[2]);
    this.polhode.showUpTo(where.i + 1);
    this.herpolhodeLine.showUpTo(where.i + 1);
  };

  // World-space numbers for the tests: the contact point, omega's tip, the ellipsoid's matrix (a unit sphere
  // mapped by it), the plane's foot point and normal, and L's arrow direction.
  PoinsotScene.prototype.probe = function () {
    this.ctx.scene.updateMatrixWorld(true);
    var a = this.bodyScene.omegaArrow, m = this.bodyScene.momentumArrow;
    var tip = a.localToWorld(new THREE.Vector3(0, a.userData.length, 0));
    var n = new THREE.Vector3(0, 0, 1).applyQuaternion(this.plane.getWorldQuaternion(new THREE.Quaternion()));
    var ld = new THREE.Vector3(0, 1, 0).applyQuaternion(m.quaternion);
    var c = this.contact.getWorldPosition(new THREE.Vector3());
    var f = this.plane.getWorldPosition(new THREE.Vector3());
    return { contact: [c.x, c.y, c.z], omegaTip: [tip.x, tip.y, tip.z],
             ellipsoidMatrix: this.ellipsoid.matrixWorld.elements.slice(),
             planePoint: [f.x, f.y, f.z], planeNormal: [n.x, n.y, n.z], LArrow: [ld.x, ld.y, ld.z],
             scale: this.scale, distance: this.distance };
  };

  return PoinsotScene;
})();
