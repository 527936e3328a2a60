// Loop subdivision of a triangle mesh (OFF in, OFF out), for the large-mesh
// runs of benchmark/atlas_vs_xatlas.sh: every step quadruples the faces.
// Warren's weights inside, the cubic B-spline rules on borders.
//
//   node benchmark/loop_subdivide.cjs IN.off OUT.off STEPS
'use strict';
const fs = require('fs');

function fail(message) { process.stderr.write('loop_subdivide: ' + message + '\n'); process.exit(1); }

function readOff(path) {
  const tok = fs.readFileSync(path, 'utf8').replace(/#[^\n]*/g, ' ').split(/\s+/).filter(s => s.length);
  if (tok[0] !== 'OFF') fail(path + ': not an OFF file');
  const nv = +tok[1], nf = +tok[2];
  const P = new Float64Array(3 * nv), F = new Uint32Array(3 * nf);
  let i = 4;
  for (let v = 0; v < 3 * nv; ++v) P[v] = +tok[i++];
  for (let f = 0; f < nf; ++f) {
    if (+tok[i++] !== 3) fail(path + ': face ' + f + ' is not a triangle');
    for (let k = 0; k < 3; ++k) F[3 * f + k] = +tok[i++];
  }
  return { P, F };
}

function step({ P, F }) {
  const nv = P.length / 3, nf = F.length / 3;
  const edge = new Map(); // min*nv+max → { id, opposite corners, count }
  const key = (a, b) => (a < b ? a * nv + b : b * nv + a);
  const E = []; // [a, b, o1, o2 or -1]
  const edgeOfCorner = new Uint32Array(3 * nf);
  for (let f = 0; f < nf; ++f)
    for (let k = 0; k < 3; ++k) {
      const a = F[3 * f + k], b = F[3 * f + (k + 1) % 3], o = F[3 * f + (k + 2) % 3];
      const K = key(a, b);
      let e = edge.get(K);
      if (e === undefined) { e = E.length; edge.set(K, e); E.push([a, b, o, -1]); }
      else if (E[e][3] === -1) E[e][3] = o;
      else fail('edge ' + a + '-' + b + ' has more than two faces');
      edgeOfCorner[3 * f + k] = e;
    }
  const Q = new Float64Array(3 * (nv + E.length));
  const sum = new Float64Array(3 * nv), valence = new Uint32Array(nv);
  const bsum = new Float64Array(3 * nv), bcount = new Uint32Array(nv);
  for (let e = 0; e < E.length; ++e) {
    const [a, b, o1, o2] = E[e];
    for (let c = 0; c < 3; ++c) {
      Q[3 * (nv + e) + c] = o2 < 0 ? 0.5 * (P[3 * a + c] + P[3 * b + c])
                                   : 0.375 * (P[3 * a + c] + P[3 * b + c]) + 0.125 * (P[3 * o1 + c] + P[3 * o2 + c]);
      sum[3 * a + c] += P[3 * b + c]; sum[3 * b + c] += P[3 * a + c];
      if (o2 < 0) { bsum[3 * a + c] += P[3 * b + c]; bsum[3 * b + c] += P[3 * a + c]; }
    }
    ++valence[a]; ++valence[b];
    if (o2 < 0) { ++bcount[a]; ++bcount[b]; }
  }
  for (let v = 0; v < nv; ++v) {
    const n = valence[v];
    if (bcount[v] > 0) {
      for (let c = 0; c < 3; ++c)
        Q[3 * v + c] = bcount[v] === 2 ? 0.75 * P[3 * v + c] + 0.125 * bsum[3 * v + c] : P[3 * v + c];
      continue;
    }
    const beta = n === 3 ? 3 / 16 : 3 / (8 * n);
    for (let c = 0; c < 3; ++c) Q[3 * v + c] = (1 - n * beta) * P[3 * v + c] + beta * sum[3 * v + c];
  }
  const G = new Uint32Array(12 * nf);
  for (let f = 0; f < nf; ++f) {
    const a = F[3 * f], b = F[3 * f + 1], c = F[3 * f + 2];
    const ab = nv + edgeOfCorner[3 * f], bc = nv + edgeOfCorner[3 * f + 1], ca = nv + edgeOfCorner[3 * f + 2];
    G.set([a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca], 12 * f);
  }
  return { P: Q, F: G };
}

const [inPath, outPath, steps] = process.argv.slice(2);
if (!inPath || !outPath || !(+steps >= 1)) fail('usage: node loop_subdivide.cjs IN.off OUT.off STEPS');
let m = readOff(inPath);
for (let s = 0; s < +steps; ++s) m = step(m);
const nv = m.P.length / 3, nf = m.F.length / 3;
const fd = fs.openSync(outPath, 'w');
let buf = ['OFF', nv + ' ' + nf + ' 0'];
const flush = () => { fs.writeSync(fd, buf.join('\n') + '\n'); buf = []; };
for (let v = 0; v < nv; ++v) { buf.push(m.P[3 * v] + ' ' + m.P[3 * v + 1] + ' ' + m.P[3 * v + 2]); if (buf.length > 65536) flush(); }
for (let f = 0; f < nf; ++f) { buf.push('3 ' + m.F[3 * f] + ' ' + m.F[3 * f + 1] + ' ' + m.F[3 * f + 2]); if (buf.length > 65536) flush(); }
flush();
fs.closeSync(fd);
process.stdout.write(outPath + ': ' + nv + ' vertices, ' + nf + ' faces\n');
