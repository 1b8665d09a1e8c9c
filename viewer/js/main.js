// poinsot view: reads the page's data, builds the scenes, runs the clock and exposes `window.poinsotView` (the
// player, the data and a probe of the construction) for tests and for the curious.
(function () {
  'use strict';
  var M = PV.math;
  var data = JSON.parse(document.getElementById('poinsot-data').textContent);

  function buildTrack() {
    var f = {};
    if (data.kind === 'multibody') {
      data.bodies.forEach(function (b, k) {
        f['x' + k] = { data: b.x, width: 3, kind: 'vec' };
        f['q' + k] = { data: b.q, width: 4, kind: 'quat' };
        f['w' + k] = { data: b.omega_body, width: 3, kind: 'vec' };
      });
    } else {
      f.q = { data: data.q, width: 4, kind: 'quat' };
      f.omega_body = { data: data.omega_body, width: 3, kind: 'vec' };
      f.L_space = { data: data.L_space, width: 3, kind: 'vec' };
      f.energy = { data: data.energy, width: 1, kind: 'vec' };
    }
    return new PV.Track(data.t, f);
  }

  var stage = document.getElementById('stage');
  var renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setSize(stage.clientWidth, stage.clientHeight);
  stage.appendChild(renderer.domElement);
  var scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf4f4f2);
  scene.add(new THREE.AmbientLight(0xffffff, 0.55));
  var camera = new THREE.PerspectiveCamera(40, stage.clientWidth / stage.clientHeight, 1e-3, 1e4);
  var headlight = new THREE.DirectionalLight(0xffffff, 0.6);  // moves with the camera (either camera frame)
  headlight.position.set(0.4, 0.6, 1);
  camera.add(headlight);
  scene.add(camera);

  var track = buildTrack();
  var ctx = { data: data, track: track, scene: scene, length: 1, center: [0, 0, 0] };
  var scenes = [], poinsot = null, main;
  var multipliers = null, optimal = null;
  if (data.kind === 'multibody') {
    main = new PV.MultibodyScene(ctx);
    scenes.push(main);
    if (data.model_from_scenario) {  // the multipliers are computed from the model
      multipliers = new PV.MultipliersScene(ctx, main);
      scenes.push(multipliers);
    }
  } else {
    main = new PV.BodyScene(ctx);
    scenes.push(main);
    // Poinsot's construction needs a torque-free body that turns (L = 0 has no invariable plane).
    if (data.torque === 'none' && M.norm(data.initial.L_space) > 0 && data.initial.energy > 0) {
      poinsot = new PV.PoinsotScene(ctx, main);
      scenes.push(poinsot);
    }
    if (data.top) scenes.push(new PV.TopScene(ctx, main));
    if (data.optimal) {
      optimal = new PV.OptimalScene(ctx, main);
      scenes.push(optimal);
    }
  }
  var overlays = [];
  scenes.forEach(function (s) { overlays = overlays.concat(s.overlays); });
  overlays.forEach(function (o) { o.initial = o.on; });
  var initialShape = main.shapeShown();
  camera.near = ctx.length * 1e-3; camera.far = ctx.length * 1e3;
  camera.updateProjectionMatrix();
  // The camera's distance: the construction is larger than the body, the torque's bounds too.
  var orbit = new PV.Orbit(renderer.domElement, (poinsot ? 5.5 : optimal ? 7 : 4.5) * ctx.length);

  document.getElementById('title').textContent = (data.title || data.scenario.split('/').pop()) + '  (' +
      data.method + ', ' +
      data.frames + ' frames of ' + data.samples + ' samples)';
  var legend = document.getElementById('legend');
  scenes.forEach(function (s) {
    s.legend.forEach(function (item) {
      var div = document.createElement('div');
      div.innerHTML = '<span class="swatch" style="background:' + item[0] + '"></span>';
      div.appendChild(document.createTextNode(item[1]));
      legend.appendChild(div);
    });
  });

  function shapeName(shown) { return shown === 'surface' ? 'shape' : shown; }
  var player = {
    t0: data.t[0], t1: data.t[data.t.length - 1], n: track.n, time: data.t[0], speed: 1, playing: false,
    where: { i: 0, u: 0 }, cameraMode: 'space',
    seek: function (time) {
      player.time = Math.min(player.t1, Math.max(player.t0, time));
      player.render();
    },
    frame: function (i) { player.seek(data.t[Math.min(track.n - 1, Math.max(0, i))]); },
    step: function (di) {
      player.playing = false;
      var w = track.locate(player.time);
      player.frame(di < 0 && w.u > 0 ? w.i : w.i + di);
    },
    toggle: function () {
      if (!player.playing && player.time >= player.t1) player.time = player.t0;
      player.playing = !player.playing;
      last = performance.now();
      player.render();
    },
    setSpeed: function (s) { player.speed = Math.min(10, Math.max(0.1, s)); controls.refresh(); },
    showOverlay: function (o, on) {
      o.on = on;
      o.objects.forEach(function (obj) { obj.userData.enabled = on; obj.visible = on; });
      player.render();
    },
    toggleShape: function () {
      var shown = main.toggleShape();
      var cb = document.getElementById('overlay-shape');
      if (cb) {
        var text = cb.parentNode.lastChild;
        text.textContent = text.textContent.replace(/\((shape|box|ellipsoid)\)/, '(' + shapeName(shown) + ')');
      }
      player.render();
    },
    resetView: function () { orbit.reset(); player.render(); },
    // Back to the state the page opened in: paused at the first frame, 1x, space-fixed camera, the view and
    // every overlay as they were, the first shape, the help closed.
    restore: function () {
      player.playing = false; player.speed = 1; player.cameraMode = 'space';
      document.getElementById('camera').value = 'space';
      document.getElementById('help').hidden = true;
      for (var k = 0; k < 3 && main.shapeShown() !== initialShape; k++) player.toggleShape();
      overlays.forEach(function (o) {
        if (o.on !== o.initial) { controls.boxes[o.key].checked = o.initial; player.showOverlay(o, o.initial); }
      });
      orbit.reset();
      if (initialChart && chart.key !== initialChart) player.showChart(initialChart);
      player.seek(player.t0);
    },
    // Moves every object to the current time (no drawing).
    update: function () {
      player.where = track.locate(player.time);
      scenes.forEach(function (s) { s.update(player.time, player.where); });
      overlays.forEach(function (o) {  // arrows hide themselves at zero length; the toggles win
        if (!o.on) o.objects.forEach(function (obj) { obj.visible = false; });
      });
    },
    render: function () {
      player.update();
      var off = orbit.offset(), up = [0, 0, 1];
      if (player.cameraMode === 'body') {
        var q = data.kind === 'multibody' ? track.value('q0', player.time) : main.q;
        off = M.rotate(q, off); up = M.rotate(q, up);
      }
      var target = data.kind === 'multibody' && player.cameraMode === 'body' ? track.value('x0', player.time)
                                                                              : ctx.center;
      camera.position.set(target[0] + off[0], target[1] + off[1], target[2] + off[2]);
      camera.up.set(up[0], up[1], up[2]);
      camera.lookAt(target[0], target[1], target[2]);
      renderer.render(scene, camera);
      if (chart) chart.draw(player.time);
      if (controls) controls.refresh();
    }
  };

  var chart = null, controls = null, initialChart = null;
  var chartCanvas = document.getElementById('chart');
  function column(name, width, k) {
    var out = [];
    for (var i = 0; i < track.n; i++) out.push(track.fields[name].data[i * width + k]);
    return out;
  }
  if (data.kind === 'multibody' && data.energy_error) {
    chart = new PV.Chart(chartCanvas, data.t,
                         [{ label: 'E \u2212 E\u2080', color: '#d62728', values: data.energy_error }],
                         'E \u2212 E\u2080 (J)', player.seek);
  } else {
    var name = data.kind === 'multibody' ? 'w0' : 'omega_body';
    var omegaSeries = ['x', 'y', 'z'].map(function (c, k) {
      return { label: '\u03c9' + c, color: ['#d62728', '#2ca02c', '#1f77b4'][k], values: column(name, 3, k) };
    });
    if (optimal) {  // a choice of charts: the control, the switching functions, omega
      var views = optimal.chartViews(omegaSeries), select = document.getElementById('chart-view');
      views.forEach(function (v) {
        var opt = document.createElement('option');
        opt.value = v.key; opt.textContent = v.label;
        select.appendChild(opt);
      });
      select.hidden = false;
      var showView = function (key) {
        var v = views.filter(function (w) { return w.key === key; })[0];
        chart = new PV.Chart(chartCanvas, data.t, v.series, v.yLabel, player.seek, v.marks);
        chart.key = key;
        select.value = key;
        player.render();
      };
      select.addEventListener('change', function () { showView(select.value); });
      chart = new PV.Chart(chartCanvas, data.t, views[0].series, views[0].yLabel, player.seek, views[0].marks);
      chart.key = views[0].key;
      player.showChart = showView;
      initialChart = views[0].key;
    } else {
      chart = new PV.Chart(chartCanvas, data.t, omegaSeries, (data.kind === 'multibody' ? data.bodies[0].name +
                           ' ' : '') + '\u03c9 body (rad/s)', player.seek);
    }
  }
  controls = new PV.Controls(player, overlays);

  var last = 0;  // the time (ms) of the last frame drawn while playing
  function tick(now) {
    if (player.playing) {
      player.time += Math.max(0, now - last) / 1000 * player.speed;
      last = now;
      if (player.time >= player.t1) { player.time = player.t1; player.playing = false; }
      player.render();
    }
    requestAnimationFrame(tick);
  }
  window.addEventListener('resize', function () {
    renderer.setSize(stage.clientWidth, stage.clientHeight);
    camera.aspect = stage.clientWidth / stage.clientHeight;
    camera.updateProjectionMatrix();
    player.render();
  });
  player.render();
  requestAnimationFrame(tick);

  window.poinsotView = {
    data: data, track: track, player: player, scene: scene,
    construction: poinsot,  // null unless torque-free
    probe: function () { return poinsot ? poinsot.probe() : null; },
    // The drawn shapes of the body (or of every body): their three.js group's userData (shown, order, box,
    // ellipsoid, surface).
    bodyShapes: function () {
      return (data.kind === 'multibody' ? main.bodies : [main]).map(function (b) { return b.shapes.userData; });
    },
    multipliers: function () { return multipliers ? multipliers.probe() : null; },
    optimal: function () { return optimal ? optimal.probe() : null; },
    chart: function () { return chart; },
    jointGap: function () { return data.kind === 'multibody' ? main.jointGap() : null; },
    // Sets the time (s) and moves the objects there without drawing (for tests that read the scene).
    moveTo: function (t) { player.time = Math.min(player.t1, Math.max(player.t0, t)); player.update(); },
    ready: true,  // set last: the scenes are built and the first frame is drawn
    bodyQuaternion: function () {  // [w, x, y, z] of the body as drawn
      var g = data.kind === 'multibody' ? main.bodies[0].group : main.group;
      return [g.quaternion.w, g.quaternion.x, g.quaternion.y, g.quaternion.z];
    }
  };
})();
