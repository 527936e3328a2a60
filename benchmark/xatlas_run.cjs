// Runs xatlas (npm's WebAssembly build `xatlas-web`, default chart and pack
// options) on one triangle mesh (OFF or OBJ) and writes an atlas OBJ: the
// input's `v` lines in their order, one `vt` per xatlas output vertex (its uv,
// in xatlas's texel units), `f v/vt` per input triangle in input order.
//
//   node benchmark/xatlas_run.cjs MESH OUT.obj
//
// `xatlas-web` is built for emscripten's web target: it refuses node unless
// it sees a browser. The two globals below are the whole shim; the wasm bytes
// are handed over as `wasmBinary` (no fetch). The module is looked up through
// NODE_PATH (benchmark/atlas_vs_xatlas.sh installs it under the build dir).
'use strict';
const fs = require('fs');

function fail(message) { process.stderr.write('xatlas_run: ' + message + '\n'); process.exit(1); }

function readMesh(path) {
  const text = fs.readFileSync(path, 'utf8');
  const pos = [], tri = [];
  if (/\.off$/i.test(path)) {
    // Line by line: COFF's colours and comments after the numbers are skipped.
    const lines = text.split('\n').map(l => l.replace(/#.*/, '').trim()).filter(l => l.length);
    if (!/^[CN]*OFF/.test(lines[0])) fail(path + ': not an OFF file');
    let head = lines[0].replace(/^[CN]*OFF/, '').trim().split(/\s+/).filter(s => s.length);
    let at = 1;
    if (head.length < 2) head = lines[at++].split(/\s+/);
    const nv = +head[0], nf = +head[1];
    for (let v = 0; v < nv; ++v, ++at) { const t = lines[at].split(/\s+/); pos.push(+t[0], +t[1], +t[2]); }
    for (let f = 0; f < nf; ++f, ++at) {
      const t = lines[at].split(/\s+/);
      if (+t[0] !== 3) fail(path + ': face ' + f + ' has ' + t[0] + ' vertices (triangles only)');
      tri.push(+t[1], +t[2], +t[3]);
    }
  } else {
    let f = 0;
    for (const line of text.split('\n')) {
      const t = line.trim().split(/\s+/);
      if (t[0] === 'v') pos.push(+t[1], +t[2], +t[3]);
      else if (t[0] === 'f') {
        if (t.length !== 4) fail(path + ': face ' + f + ' has ' + (t.length - 1) + ' vertices (triangles only)');
        for (let k = 1; k < 4; ++k) tri.push(parseInt(t[k].split('/')[0], 10) - 1);
        ++f;
      }
    }
  }
  return { pos, tri };
}

async function main() {
  const [meshPath, outPath] = process.argv.slice(2);
  if (!meshPath || !outPath) fail('usage: node xatlas_run.cjs MESH OUT.obj');
  const { pos, tri } = readMesh(meshPath);
  if (pos.length / 3 > 65535) fail(meshPath + ': ' + pos.length / 3 + ' vertices; xatlas-web reads 16-bit indices (at most 65535 vertices)');
  const t0 = process.hrtime.bigint();
  globalThis.window = globalThis;
  globalThis.document = {};
  const factory = require('xatlas-web');
  const wasmBinary = fs.readFileSync(require.resolve('xatlas-web/dist/xatlas-web.wasm'));
  const log = [];
  const m = await factory({ wasmBinary, print: s => log.push(s), printErr: s => log.push(s) }).ready;
  m.createAtlas();
  const nv = pos.length / 3;
  const info = m.createMesh(nv, tri.length, false, false);
  m.HEAPF32.set(Float32Array.from(pos), info.positionOffset / 4);
  m.HEAPU16.set(Uint16Array.from(tri), info.indexOffset / 2); // this build reads 16-bit indices
  const status = m.addMesh();
  if (status !== 0) fail('xatlas AddMesh returned ' + status + ' ' + log.join(' | '));
  m.generateAtlas();
  const d = m.getMeshData(info.meshId);
  const uv = new Float32Array(m.HEAPF32.buffer, d.uvOffset, 2 * d.newVertexCount).slice();
  const idx = new Uint32Array(m.HEAPU32.buffer, d.indexOffset, d.newIndexCount).slice();
  const orig = new Uint32Array(m.HEAPU32.buffer, d.originalIndexOffset, d.newVertexCount).slice();
  m.destroyAtlas();
  const seconds = Number(process.hrtime.bigint() - t0) / 1e9;
  if (idx.length !== tri.length) fail('xatlas returned ' + idx.length / 3 + ' triangles for ' + tri.length / 3);
  let moved = 0, firstMoved = -1;
  for (let f = 0; f < tri.length / 3; ++f)
    for (let k = 0; k < 3; ++k)
      if (orig[idx[3 * f + k]] !== tri[3 * f + k]) { if (firstMoved < 0) firstMoved = f; ++moved; break; }
  // Kept as xatlas gave them (the input's vertices, xatlas's uv): the score
  // sees what a user would get, typically a degenerate uv triangle.
  if (moved > 0)
    process.stderr.write('xatlas_run: xatlas returned ' + moved + ' triangles on other vertices than the input\'s (first: face ' +
                         firstMoved + ', input ' + tri.slice(3 * firstMoved, 3 * firstMoved + 3) + ', xatlas ' +
                         [0, 1, 2].map(k => orig[idx[3 * firstMoved + k]]) + ')\n');
  const out = [];
  for (let v = 0; v < nv; ++v) out.push('v ' + pos[3 * v] + ' ' + pos[3 * v + 1] + ' ' + pos[3 * v + 2]);
  for (let i = 0; i < d.newVertexCount; ++i) out.push('vt ' + uv[2 * i] + ' ' + uv[2 * i + 1]);
  for (let f = 0; f < tri.length / 3; ++f) {
    const c = [];
    for (let k = 0; k < 3; ++k) {
      const n = idx[3 * f + k];
      c.push((tri[3 * f + k] + 1) + '/' + (n + 1));
    }
    out.push('f ' + c.join(' '));
  }
  fs.writeFileSync(outPath, out.join('\n') + '\n');
  process.stdout.write(JSON.stringify({ faces: tri.length / 3, xatlas_vertices: d.newVertexCount, xatlas_seconds: seconds, faces_on_other_vertices: moved }) + '\n');
}
main().catch(e => fail(String(e)));
