// poinsot view: small vector and rotation helpers on plain arrays (doubles), independent of three.js.
// Quaternions are [w, x, y, z] (unit, R maps body to space); matrices are arrays of rows.
var PV = window.PV || {};
window.PV = PV;

PV.math = (function () {
  'use strict';
  function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  function cross(a, b) {
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  }
  function norm(a) { return Math.sqrt(dot(a, a)); }
  function scale(a, s) { return [a[0] * s, a[1] * s, a[2] * s]; }
  function add(a, b) { return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]; }
  function sub(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
  function lerp(a, b, u) { return [a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1]), a[2] + u * (b[2] - a[2])]; }
  function matVec(m, v) { return [dot(m[0], v), dot(m[1], v), dot(m[2], v)]; }
  function column(m, k) { return [m[0][k], m[1][k], m[2][k]]; }

  // R v for the unit quaternion q = [w, x, y, z]: v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z).
  function rotate(q, v) {
    var u = [q[1], q[2], q[3]];
    var t = scale(cross(u, v), 2);
    return add(add(v, scale(t, q[0])), cross(u, t));
  }
  // R^T v.
  function rotateInverse(q, v) { return rotate([q[0], -q[1], -q[2], -q[3]], v); }

  // Spherical linear interpolation between unit quaternions along the shorter arc (q and -q are the same
  // rotation); u = 0 returns qa itself and u = 1 qb itself (or its negative), exactly.
  function slerp(qa, qb, u) {
    if (u === 0) return qa.slice();
    var c = qa[0] * qb[0] + qa[1] * qb[1] + qa[2] * qb[2] + qa[3] * qb[3];
    var b = qb;
    if (c < 0) { c = -c; b = [-qb[0], -qb[1], -qb[2], -qb[3]]; }
    if (u === 1) return b.slice();
    var wa, wb;
    if (c > 0.9999999) {  // nearly equal: the chord is the arc to 1e-14; normalise below
      wa = 1 - u; wb = u;
    } else {
      var theta = Math.acos(c), s = Math.sin(theta);
      wa = Math.sin((1 - u) * theta) / s;
      wb = Math.sin(u * theta) / s;
    }
    var q = [wa * qa[0] + wb * b[0], wa * qa[1] + wb * b[1], wa * qa[2] + wb * b[2], wa * qa[3] + wb * b[3]];
    var n = Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    return [q[0] / n, q[1] / n, q[2] / n, q[3] / n];
  }

  // Eigenvalues and unit eigenvectors of the symmetric matrix s = [xx, yy, zz, xy, xz, yz] by cyclic Jacobi
  // rotations (converges quadratically; 50 sweeps are never reached): {values: [3], vectors: [3 arrays]},
  // s = sum_k values[k] vectors[k] vectors[k]^T.
  function symmetricEigen(s) {
    var a = [[s[0], s[3], s[4]], [s[3], s[1], s[5]], [s[4], s[5], s[2]]];
    var v = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];  // columns: the eigenvectors
    for (var sweep = 0; sweep < 50; sweep++) {
      var off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
      var scaleSq = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2] + 2 * off;
      if (off <= 1e-32 * scaleSq) break;
      for (var p = 0; p < 2; p++) {
        for (var q = p + 1; q < 3; q++) {
          if (a[p][q] === 0) continue;
          var theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
          var t = (theta >= 0 ? 1 : -1) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
          var c = 1 / Math.sqrt(t * t + 1), sn = t * c;
          for (var k = 0; k < 3; k++) {  // a <- a G (columns p, q)
            var akp = a[k][p], akq = a[k][q];
            a[k][p] = c * akp - sn * akq; a[k][q] = sn * akp + c * akq;
          }
          for (k = 0; k < 3; k++) {  // a <- G^T a (rows p, q)
            var apk = a[p][k], aqk = a[q][k];
            a[p][k] = c * apk - sn * aqk; a[q][k] = sn * apk + c * aqk;
          }
          for (k = 0; k < 3; k++) {
            var vkp = v[k][p], vkq = v[k][q];
            v[k][p] = c * vkp - sn * vkq; v[k][q] = sn * vkp + c * vkq;
          }
        }
      }
    }
    return { values: [a[0][0], a[1][1], a[2][2]], vectors: [column(v, 0), column(v, 1), column(v, 2)] };
  }

  return { symmetricEigen: symmetricEigen, dot: dot, cross: cross, norm: norm, scale: scale, add: add, sub: sub,
           lerp: lerp, matVec: matVec,
           column: column, rotate: rotate, rotateInverse: rotateInverse, slerp: slerp };
})();
