// poinsot view: the page's controls (play, speed, time slider, frame steps, camera, overlays, help) and their
// keyboard shortcuts. `player` is the object of main.js (time, speed, playing, seek, step, ...).
PV.Controls = (function () {
  'use strict';

  function $(id) { return document.getElementById(id); }

  function Controls(player, overlays) {
    this.player = player;
    var self = this, p = player;
    var slider = $('time');
    slider.min = p.t0; slider.max = p.t1;
    $('play').addEventListener('click', function () { p.toggle(); });
    $('step-back').addEventListener('click', function () { p.step(-1); });
    $('step-fwd').addEventListener('click', function () { p.step(1); });
    slider.addEventListener('input', function () { p.seek(parseFloat(slider.value)); });
    $('speed').addEventListener('input', function () { p.setSpeed(Math.pow(10, parseFloat($('speed').value))); });
    $('camera').addEventListener('change', function () { p.cameraMode = $('camera').value; p.render(); });
    $('reset').addEventListener('click', function () { p.resetView(); });
    $('help-button').addEventListener('click', function () { self.toggleHelp(); });

    var box = $('overlays');
    this.boxes = {};
    overlays.forEach(function (o, k) {
      var label = document.createElement('label');
      var cb = document.createElement('input');
      cb.type = 'checkbox'; cb.checked = o.on; cb.id = 'overlay-' + o.key;
      cb.addEventListener('change', function () { p.showOverlay(o, cb.checked); });
      label.appendChild(cb);
      label.appendChild(document.createTextNode(' ' + (k < 9 ? '[' + (k + 1) + '] ' : '') + o.label));
      box.appendChild(label);
      self.boxes[o.key] = cb;
      p.showOverlay(o, o.on);
    });

    this.keys = [
      ['space', 'play / pause', function () { p.toggle(); }],
      ['\u2190 / \u2192', 'previous / next frame', null],
      ['- / +', 'slower / faster (0.1\u00d7 to 10\u00d7 real time)', null],
      ['Home / End', 'first / last frame', null],
      ['r', 'reset the view', function () { p.resetView(); }],
      ['c', 'space-fixed / body-fixed camera', function () {
        $('camera').value = $('camera').value === 'space' ? 'body' : 'space';
        p.cameraMode = $('camera').value; p.render();
      }],
      ['b', 'the scenario\'s shape / box / ellipsoid of the same inertia', function () { p.toggleShape(); }],
      ['1 ... 9', 'toggle the overlays, in the order listed', null],
      ['h or ?', 'this help', function () { self.toggleHelp(); }]
    ];
    var table = $('help-keys');
    this.keys.forEach(function (k) {
      var row = table.insertRow();
      row.insertCell().textContent = k[0];
      row.insertCell().textContent = k[1];
    });
    document.addEventListener('keydown', function (e) { self.onKey(e, overlays); });
  }

  Controls.prototype.toggleHelp = function () { $('help').hidden = !$('help').hidden; };

  Controls.prototype.onKey = function (e, overlays) {
    var p = this.player, k = e.key;
    if (k === ' ') p.toggle();
    else if (k === 'ArrowLeft') p.step(-1);
    else if (k === 'ArrowRight') p.step(1);
    else if (k === '+' || k === '=') p.setSpeed(p.speed * 1.25);
    else if (k === '-') p.setSpeed(p.speed / 1.25);
    else if (k === 'Home') p.seek(p.t0);
    else if (k === 'End') p.seek(p.t1);
    else if (k === 'r') p.resetView();
    else if (k === 'c') this.keys[5][2]();
    else if (k === 'b') p.toggleShape();
    else if (k === 'h' || k === '?') this.toggleHelp();
    else if (k >= '1' && k <= '9' && overlays[k - 1]) {
      var cb = this.boxes[overlays[k - 1].key];
      cb.checked = !cb.checked;
      p.showOverlay(overlays[k - 1], cb.checked);
    } else return;
    e.preventDefault();
  };

  // Shows the player's time, speed and state.
  Controls.prototype.refresh = function () {
    var p = this.player;
    $('time').value = p.time;
    $('time-label').textContent = 't = ' + p.time.toFixed(3) + ' s / ' + p.t1.toPrecision(4) + ' s   (frame ' +
        (p.where.i + 1) + ' of ' + p.n + ')';
    $('speed').value = Math.log10(p.speed);
    $('speed-label').textContent = p.speed.toPrecision(2) + '\u00d7';
    $('play').innerHTML = p.playing ? '&#10074;&#10074;' : '&#9654;';
  };

  return Controls;
})();
