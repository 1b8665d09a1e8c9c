// poinsot view: the Lagrange multipliers of a multibody file made visible. At every joint the reaction on
// body a (the force, N, and the couple, N·m, space frame) as arrows from the joint's point; at every body's
// centre of mass the principal constraint stresses: the eigen-decomposition of ∫σ dv = −R Λ Rᵀ (N·m), each
// principal direction as a pair of arrows pointing out (tension, > 0) or in (compression, < 0), as long as
// the principal value. Each kind has one scale over the whole run (see the constructor), stated in the
// legend. The data are per frame (view_multipliers.hpp): joints[k].reaction
// (Fx Fy Fz Cx Cy Cz), bodies[i].lambda (Λ's symmetric part, body frame: xx yy zz xy xz yz).
PV.MultipliersScene = (function () {
  'use strict';
  var M = PV.math, D = PV.draw;
  var FORCE = 0xd62728, COUPLE = 0x9467bd, TENSION = 0xe6550d, COMPRESSION = 0x3182bd;

  // Per frame, the largest `norm` of the fields `names` (array of one value per frame).
  function largest(track, names, norm) {
    var out = [];
    for (var i = 0; i < track.n; i++) {
      var m = 0;
      names.forEach(function (name) { m = Math.max(m, norm(track.at(name, i))); });
      out.push(m);
    }
    return out;
  }
  // The value below which a fraction `p` of `values` lie (p = 1: the largest).
  function quantile(values, p) {
    var s = values.slice().sort(function (a, b) { return a - b; });
    return s.length ? s[Math.min(s.length - 1, Math.floor(p * s.length))] : 0;
  }
  function forceNorm(r) { return M.norm([r[0], r[1], r[2]]); }
  function coupleNorm(r) { return M.norm([r[3], r[4], r[5]]); }
  function frobenius(s) {
    return Math.sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
  }
  function short(v) { return v.toPrecision(3); }

  // An arrow drawn over the bodies: a reaction along a rod, or a stress along its axis, lies inside it.
  function overlayArrow(color) {
    var a = D.arrow(color);
    [a.line, a.cone].forEach(function (part) { part.material.depthTest = false; part.renderOrder = 10; });
    return a;
  }

  // `multibody` is the MultibodyScene (its joints' balls and bodies' groups are placed before this updates).
  function MultipliersScene(ctx, multibody) {
    var data = ctx.data, track = ctx.track, span = 2 * ctx.length;
    this.ctx = ctx; this.multibody = multibody;
    data.joints.forEach(function (j, k) { track.fields['r' + k] = { data: j.reaction, width: 6, kind: 'vec' }; });
    data.bodies.forEach(function (b, i) { track.fields['s' + i] = { data: b.lambda, width: 6, kind: 'vec' }; });
    var joints = data.joints.map(function (j, k) { return 'r' + k; });
    var bodies = data.bodies.map(function (b, i) { return 's' + i; });
    var forces = largest(track, joints, forceNorm), couples = largest(track, joints, coupleNorm);
    var stresses = largest(track, bodies, frobenius);
    // m of arrow per N, per N·m, per N·m of principal stress integral: the frames' largest value at the 90th
    // percentile over the run is a quarter (a fifth) of the scene, so that the whip of a chain, a few frames
    // of large forces, does not shrink every other frame's arrows to nothing (those frames' are longer).
    var fmax = quantile(forces, 1), cmax = quantile(couples, 1), smax = quantile(stresses, 1);
    var f90 = quantile(forces, 0.9) || fmax, c90 = quantile(couples, 0.9) || cmax;
    var s90 = quantile(stresses, 0.9) || smax;
    this.forceScale = f90 > 0 ? 0.25 * span / f90 : 0;
    this.coupleScale = c90 > 0 ? 0.25 * span / c90 : 0;
    this.stressScale = s90 > 0 ? 0.2 * span / s90 : 0;
    this.least = { force: 1e-9 * fmax, couple: 1e-9 * cmax };  // below: round-off, not drawn

    this.reactions = data.joints.map(function (j) {
      var force = overlayArrow(FORCE), couple = overlayArrow(COUPLE);
      ctx.scene.add(force); ctx.scene.add(couple);
      return { force: force, couple: couple };
    });
    this.stresses = data.bodies.map(function () {
      var arrows = [];
      for (var k = 0; k < 6; k++) {  // principal direction k >> 1, the side of the centre k & 1
        var a = overlayArrow(TENSION);
        ctx.scene.add(a);
        arrows.push(a);
      }
      return arrows;
    });
    var reactionObjects = [], stressObjects = [];
    this.reactions.forEach(function (r) { reactionObjects.push(r.force, r.couple); });
    this.stresses.forEach(function (s) { stressObjects = stressObjects.concat(s); });
    this.overlays = [
      { key: 'reactions', label: 'joint reactions on body a', objects: reactionObjects, on: false },
      { key: 'stress', label: 'principal constraint stresses (\u039b)', objects: stressObjects, on: false }
    ];
    this.legend = [];
    if (fmax > 0) this.legend.push(['#d62728', 'joint force, 1 m = ' + short(1 / this.forceScale) + ' N']);
    if (cmax > 0) this.legend.push(['#9467bd', 'joint couple, 1 m = ' + short(1 / this.coupleScale) + ' N\u00b7m']);
    if (smax > 0) {
      this.legend.push(['#e6550d', 'tension \u222b\u03c3 dv = \u2212R\u039bR\u1d40, 1 m = ' +
                        short(1 / this.stressScale) + ' N\u00b7m'],
                       ['#3182bd', 'compression (arrows pointing in)']);
    }
  }

  MultipliersScene.prototype.update = function (time) {
    var track = this.ctx.track, self = this;
    this.multibody.joints.forEach(function (j, k) {
      var r = track.value('r' + k, time), p = j.ball.position, at = [p.x, p.y, p.z];
      var f = [r[0], r[1], r[2]], c = [r[3], r[4], r[5]];
      var arrows = self.reactions[k];
      arrows.force.set(at, M.norm(f) > self.least.force ? M.scale(f, self.forceScale) : [0, 0, 0]);
      arrows.couple.set(at, M.norm(c) > self.least.couple ? M.scale(c, self.coupleScale) : [0, 0, 0]);
      arrows.force.userData.value = f; arrows.couple.userData.value = c;
    });
    this.multibody.bodies.forEach(function (b, i) {
      var e = M.symmetricEigen(track.value('s' + i, time).map(function (x) { return -x; }));  // of −Λ
      var g = b.group, q = [g.quaternion.w, g.quaternion.x, g.quaternion.y, g.quaternion.z];
      var x = [g.position.x, g.position.y, g.position.z];
      for (var k = 0; k < 3; k++) {
        var len = Math.abs(e.values[k]) * self.stressScale, d = M.rotate(q, e.vectors[k]);
        for (var side = 0; side < 2; side++) {
          var a = self.stresses[i][2 * k + side], out = M.scale(d, side ? -len : len);
          var tension = e.values[k] >= 0;
          // Tension: from the centre outwards; compression: from outside towards the centre.
          a.set(tension ? x : M.add(x, out), tension ? out : M.scale(out, -1));
          a.setColor(tension ? TENSION : COMPRESSION);
          a.userData.principal = e.values[k];
        }
      }
    });
  };

  // What is drawn, read back from the arrows (for tests): per joint the force and couple (N, N·m; arrow length
  // over its scale along its direction, 0 when hidden by length) and its origin; per body the principal values
  // (N·m, signed: the arrows' length over the scale, + when they point away from the centre) and directions
  // (space frame) of the first arrow of each pair.
  MultipliersScene.prototype.probe = function () {
    var self = this;
    function vector(a, scale) {
      if (!(scale > 0)) return [0, 0, 0];  // none over the whole run
      var d = new THREE.Vector3(0, 1, 0).applyQuaternion(a.quaternion);
      return [d.x * a.userData.length / scale, d.y * a.userData.length / scale, d.z * a.userData.length / scale];
    }
    return {
      joints: this.reactions.map(function (r) {
        return { origin: [r.force.position.x, r.force.position.y, r.force.position.z],
                 force: vector(r.force, self.forceScale), couple: vector(r.couple, self.coupleScale) };
      }),
      bodies: this.multibody.bodies.map(function (b, i) {
        var c = b.group.position, out = [];
        for (var k = 0; k < 3; k++) {
          var a = self.stresses[i][2 * k], d = new THREE.Vector3(0, 1, 0).applyQuaternion(a.quaternion);
          var p = a.position, away = (p.x - c.x) * d.x + (p.y - c.y) * d.y + (p.z - c.z) * d.z >= -1e-12 *
              a.userData.length;
          out.push({ value: self.stressScale > 0 ? (away ? 1 : -1) * a.userData.length / self.stressScale : 0,
                     direction: [d.x, d.y, d.z] });
        }
        return out;
      })
    };
  };

  return MultipliersScene;
})();
