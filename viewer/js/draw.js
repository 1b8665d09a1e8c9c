// poinsot view: three.js building blocks shared by the scenes (arrows, traced lines, shapes, labels).
PV.draw = (function () {
  'use strict';

  function v3(a) { return new THREE.Vector3(a[0], a[1], a[2]); }

  // An arrow from `origin` along `vec` (scene units); set(origin, vec) moves it. The tip is kept in
  // userData.tip (world coordinates when the arrow's parent is the scene).
  function arrow(color, headFraction) {
    var a = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 1, color);
    a.userData.headFraction = headFraction || 0.15;
    a.set = function (origin, vec) {
      var len = Math.sqrt(vec[0] * vec[0] + vec[1] * vec[1] + vec[2] * vec[2]);
      a.position.set(origin[0], origin[1], origin[2]);
      a.visible = a.userData.enabled !== false && len > 0;
      a.userData.length = len;
      if (len === 0) return;
      a.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), v3(vec).divideScalar(len));
      var head = Math.min(len * 0.5, a.userData.headLength || len * a.userData.headFraction);
      a.setLength(len, head, head * 0.5);
    };
    return a;
  }

  // A line through `points` (flat array, 3 per point) of which the first `count` are drawn.
  function tracedLine(points, color, opacity) {
    var g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(points), 3));
    var m = new THREE.LineBasicMaterial({ color: color, transparent: opacity !== undefined, opacity: opacity || 1 });
    var line = new THREE.Line(g, m);
    line.frustumCulled = false;
    line.showUpTo = function (count) { g.setDrawRange(0, Math.max(0, count)); };
    return line;
  }

  // A closed line through `points` (array of [x, y, z]).
  function loop(points, color) {
    var flat = [];
    points.forEach(function (p) { flat.push(p[0], p[1], p[2]); });
    flat.push(points[0][0], points[0][1], points[0][2]);
    return tracedLine(flat, color);
  }

  // Three lines along the columns of `axes` (body frame), of lengths `lengths`, red-green-blue.
  function principalAxes(axes, lengths) {
    var group = new THREE.Group();
    var colors = [0xd62728, 0x2ca02c, 0x1f77b4];
    for (var k = 0; k < 3; k++) {
      var d = [axes[0][k] * lengths[k], axes[1][k] * lengths[k], axes[2][k] * lengths[k]];
      group.add(tracedLine([-d[0], -d[1], -d[2], d[0], d[1], d[2]], colors[k]));
    }
    return group;
  }

  // A rotation (three.js) whose columns are `axes` (array of rows, a proper rotation).
  function basis(axes) {
    var m = new THREE.Matrix4();
    m.set(axes[0][0], axes[0][1], axes[0][2], 0, axes[1][0], axes[1][1], axes[1][2], 0,
          axes[2][0], axes[2][1], axes[2][2], 0, 0, 0, 0, 1);
    return new THREE.Quaternion().setFromRotationMatrix(m);
  }

  // The body's own surface (shapes.surface: vertices and triangles about the centre of mass, body axes) as a
  // mesh, both sides lit (a mesh file's winding is not trusted).
  function surfaceMesh(surface, material) {
    var g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(surface.vertices), 3));
    g.setIndex(surface.triangles);
    g.computeVertexNormals();
    return new THREE.Mesh(g, material);
  }

  // The body as drawn (shapes from the data, in a group in the body frame about the centre of mass): its own
  // surface when the scenario gives a shape or mesh, and the uniform box and ellipsoid with its inertia
  // (along its principal axes); one of them visible, the surface first. userData.order lists what
  // userData.show(name) can show.
  function bodyShapes(shapes, color, minHalf) {
    var h = shapes.box_half_extents.map(function (x) { return Math.max(x, minHalf); });
    var a = shapes.ellipsoid_semi_axes.map(function (x) { return Math.max(x, minHalf); });
    var material = new THREE.MeshPhongMaterial({ color: color, shininess: 30, transparent: true, opacity: 0.9,
                                                 side: THREE.DoubleSide });
    var box = new THREE.Mesh(new THREE.BoxGeometry(2 * h[0], 2 * h[1], 2 * h[2]), material);
    var ell = new THREE.Mesh(new THREE.SphereGeometry(1, 32, 16), material);
    ell.scale.set(a[0], a[1], a[2]);
    var principal = new THREE.Group();
    principal.quaternion.copy(basis(shapes.axes));
    principal.add(box); principal.add(ell);
    var group = new THREE.Group();
    group.add(principal);
    var items = { box: box, ellipsoid: ell }, order = ['box', 'ellipsoid'];
    if (shapes.surface) {
      items.surface = surfaceMesh(shapes.surface, material);
      group.add(items.surface);
      order.unshift('surface');
    }
    group.userData = { box: box, ellipsoid: ell, surface: items.surface || null, halfExtents: h, order: order,
                       shown: order[0] };
    group.userData.show = function (name) {
      order.forEach(function (k) { items[k].visible = k === name; });
      group.userData.shown = name;
    };
    group.userData.next = function () {
      var u = group.userData;
      u.show(order[(order.indexOf(u.shown) + 1) % order.length]);
      return u.shown;
    };
    group.userData.show(order[0]);
    return group;
  }

  return { v3: v3, arrow: arrow, tracedLine: tracedLine, loop: loop, principalAxes: principalAxes, basis: basis,
           bodyShapes: bodyShapes };
})();
