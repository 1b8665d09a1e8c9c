// poinsot view: a small orbit control (drag to turn about the target, wheel to zoom). Written here because
// libjs-three ships OrbitControls only as a module wrapper. The camera's position is kept as spherical
// coordinates (radius, polar angle from +z, azimuth) about the target, in the camera frame; main.js turns
// that frame with the body for the body-fixed camera.
PV.Orbit = (function () {
  'use strict';

  function Orbit(element, radius) {
    this.home = { radius: radius, polar: 1.15, azimuth: -0.9 };
    this.reset();
    var self = this, dragging = false, x0 = 0, y0 = 0;
    element.addEventListener('pointerdown', function (e) {
      dragging = true; x0 = e.clientX; y0 = e.clientY;
      if (element.setPointerCapture) element.setPointerCapture(e.pointerId);
    });
    element.addEventListener('pointermove', function (e) {
      if (!dragging) return;
      self.turn(-(e.clientX - x0) * 0.008, -(e.clientY - y0) * 0.008);
      x0 = e.clientX; y0 = e.clientY;
    });
    element.addEventListener('pointerup', function () { dragging = false; });
    element.addEventListener('wheel', function (e) {
      e.preventDefault();
      self.zoom(e.deltaY > 0 ? 1.1 : 1 / 1.1);
    }, { passive: false });
  }

  Orbit.prototype.reset = function () {
    this.radius = this.home.radius; this.polar = this.home.polar; this.azimuth = this.home.azimuth;
  };
  Orbit.prototype.turn = function (dAzimuth, dPolar) {
    this.azimuth += dAzimuth;
    this.polar = Math.min(Math.PI - 0.01, Math.max(0.01, this.polar + dPolar));
  };
  Orbit.prototype.zoom = function (factor) {
    this.radius = Math.min(this.home.radius * 20, Math.max(this.home.radius / 20, this.radius * factor));
  };
  // The camera's offset from the target in the camera frame (z up).
  Orbit.prototype.offset = function () {
    var s = Math.sin(this.polar);
    return [this.radius * s * Math.cos(this.azimuth), this.radius * s * Math.sin(this.azimuth),
            this.radius * Math.cos(this.polar)];
  };
  return Orbit;
})();
