// Wrapper around the emscripten module (docs/wasm-api.md). The only place that
// touches the module: it turns the module's result-or-error value into data or a
// thrown PdesurfError, so callers never see an aborted module or a bare pointer.
import { normaliseReport } from '../state/join-report.js';
import { hasWasmSimd, SIMD_MISSING } from './wasm-features.js';

/** A solver failure with a machine-readable code (ParseError, InvalidField, ...). */
export class PdesurfError extends Error {
  constructor(code, message) {
    super(message);
    this.name = 'PdesurfError';
    this.code = code;
  }
}

const DEFAULT_MODULE_URL = '/wasm/pdesurf.js';

/**
 * Load the wasm module and return { solve(scene, {nu, nv}), module }.
 * Browser: imports /wasm/pdesurf.js (the module finds pdesurf.wasm beside itself).
 * Node: pass { moduleUrl, wasmBinary } (node's fetch cannot load a file path).
 * wasmBinary may be a promise: the worker starts fetching the .wasm while this imports the
 * module's glue code. Or wasmModule, a WebAssembly.Module or a promise of one (the worker's
 * WebAssembly.compileStreaming: compiled as it downloads).
 * An engine without WebAssembly SIMD, which the module needs, fails with code Unsupported.
 */
export async function loadSolver(opts = {}) {
  const moduleUrl = opts.moduleUrl || DEFAULT_MODULE_URL;
  if (!hasWasmSimd()) {
    // the caller's fetch or compile, started in parallel, fails too: not an unhandled rejection
    for (const pending of [opts.wasmBinary, opts.wasmModule]) Promise.resolve(pending).catch(() => {});
    throw new PdesurfError('Unsupported', SIMD_MISSING);
  }
  let factory, wasmBinary, wasmModule;
  try {
    [{ default: factory }, wasmBinary, wasmModule] = await Promise.all([import(/* @vite-ignore */ moduleUrl), opts.wasmBinary, opts.wasmModule]);
  } catch (err) {
    throw new PdesurfError('Load', `cannot load the solver module ${moduleUrl}: ${err.message}`);
  }
  if (typeof factory !== 'function') {
    throw new PdesurfError('Load', `${moduleUrl} has no default factory export`);
  }
  const moduleArgs = {};
  if (wasmBinary) moduleArgs.wasmBinary = wasmBinary;
  // A module compiled already (the worker compiles it as it streams in): instantiated here,
  // and a failure to instantiate rejects the load (emscripten's hook has no error path).
  let instantiateFailed = null;
  if (wasmModule) {
    instantiateFailed = new Promise((_, reject) => {
      moduleArgs.instantiateWasm = (imports, receive) => {
        WebAssembly.instantiate(wasmModule, imports).then((instance) => receive(instance, wasmModule), reject);
        return {};
      };
    });
  }
  if (opts.locateFile) moduleArgs.locateFile = opts.locateFile;
  // Keep emscripten's stdout/stderr out of the console unless asked for.
  moduleArgs.print = opts.print || (() => {});
  moduleArgs.printErr = opts.printErr || ((s) => console.warn('[pdesurf wasm]', s));
  let Module;
  try {
    Module = await (instantiateFailed ? Promise.race([factory(moduleArgs), instantiateFailed]) : factory(moduleArgs));
  } catch (err) {
    throw new PdesurfError('Load', `cannot start the solver module: ${err && err.message ? err.message : err}`);
  }
  if (typeof Module.solveScene !== 'function') {
    throw new PdesurfError('Load', 'the solver module has no solveScene function');
  }
  return {
    module: Module,
    solve: (scene, grid = {}) => solveWith(Module, scene, grid),
    exportCad: (scene, options = {}) => exportCadWith(Module, scene, options),
    modelMesh: (scene, grid = {}) => modelMeshWith(Module, scene, grid),
    reportBegin: (options = {}) => reportBeginWith(Module, options),
    reportStep: (budgetMs = 8) => reportStepWith(Module, budgetMs),
  };
}

// The join report of the last solve, part by part (docs/wasm-api.md): reportBegin({ crossings })
// -> { parts }; reportStep(budgetMs) -> { done, left, measured, kept, report? } (the report, in
// the shape solve(…, { joins: true }) gives, once done). Parts whose surfaces did not change
// since the previous report are kept, not measured again.
function reportBeginWith(Module, { crossings = false } = {}) {
  const res = callModule(Module, 'reportBegin', [{ crossings: Boolean(crossings) }], 'report');
  return { parts: Number(res.parts) };
}

function reportStepWith(Module, budgetMs) {
  const res = callModule(Module, 'reportStep', [Number(budgetMs)], 'report');
  const out = { done: Boolean(res.done), left: Number(res.left ?? 0), measured: Number(res.measured ?? 0), kept: Number(res.kept ?? 0) };
  if (out.done) {
    out.report = normaliseReport(res.report);
    if (!out.report) throw new PdesurfError('Internal', 'the solver returned no join report');
  }
  return out;
}

// The model's watertight mesh for the mesh exports (docs/wasm-api.md, modelMesh): { title,
// positions, normals (Float32Array, shared by the patches), parts: [{ name, body, indices }],
// bodies: [{ patches, closed, area, volume (null when open), free_edges }] }, the bodies as the report has them.
function modelMeshWith(Module, scene, { nu = 64, nv = 64 } = {}) {
  const res = callModule(Module, 'modelMesh', [sceneText(scene), nu, nv], 'mesh');
  return { title: res.title, positions: res.positions, normals: res.normals, parts: Array.from(res.parts), bodies: Array.from(res.bodies) };
}

// Module[name](...args), whose result is { ok: true, … } or { ok: false, error }, as that result
// or a PdesurfError: a module without the function is Load, a throw or no result Internal,
// a failure its own code (`what` names the call in a failure without a message).
function callModule(Module, name, args, what) {
  if (typeof Module[name] !== 'function') {
    throw new PdesurfError('Load', `this solver module has no ${name}: rebuild the wasm module`);
  }
  let res;
  try {
    res = Module[name](...args);
  } catch (err) {
    throw new PdesurfError('Internal', err instanceof Error ? err.message : `${name} threw ${String(err)}`);
  }
  if (!res || typeof res !== 'object') throw new PdesurfError('Internal', `${name} returned no result`);
  if (!res.ok) {
    const e = res.error || {};
    throw new PdesurfError(String(e.code || 'Internal'), String(e.message || `unknown ${what} error`));
  }
  return res;
}

// Every patch as a certified B-spline face, and with format 'step' or 'iges' the file's text,
// with '3dm' each body as a Brep to decode (docs/wasm-api.md, docs/cad-export.md):
// { tolerance, faces: [...], text?, shells?, breps?, archive? }.
function exportCadWith(Module, scene, { format = 'faces', tolerance, degree, onProgress } = {}) {
  const options = { format };
  if (tolerance !== undefined) options.tolerance = tolerance;
  if (degree !== undefined) options.degree = degree;
  if (typeof onProgress === 'function') options.onProgress = onProgress;
  const res = callModule(Module, 'exportCad', [sceneText(scene), options], 'export');
  const out = { title: res.title, tolerance: res.tolerance, faces: Array.from(res.faces || []), joins: Array.from(res.joins || []), text: res.text };
  // STEP: the shells the file holds ({ faces, closed, volume }; a closed one is a solid).
  if (res.shells) out.shells = Array.from(res.shells);
  // .3dm: each body one openNURBS Brep's bytes, for rhino3dm's decode (web/cad/write-3dm.js).
  if (res.breps) {
    out.breps = Array.from(res.breps, (b) => ({ closed: b.closed, faces: Array.from(b.faces), data: b.data }));
    out.archive = { archive3dm: res.archive3dm, opennurbs: res.opennurbs };
  }
  return out;
}

// The scene as JSON text, or a PdesurfError: JSON.stringify throws RangeError on a too deep
// object and TypeError on a cycle or a BigInt, and returns undefined for a function.
function sceneText(scene) {
  if (typeof scene === 'string') return scene;
  let text;
  try {
    text = JSON.stringify(scene);
  } catch (err) {
    throw new PdesurfError('InvalidField', `the scene cannot be written as JSON: ${err && err.message ? err.message : err}`);
  }
  if (typeof text !== 'string') throw new PdesurfError('InvalidField', 'the scene cannot be written as JSON');
  return text;
}

// topology: false leaves out uvs and indices (they change only with the grid; the page
// keeps its own).
function solveWith(Module, scene, { nu = 64, nv = 64, curvature = false, joins = false, crossings = false, topology = true } = {}) {
  const text = sceneText(scene);
  const analysis = Boolean(curvature) || Boolean(joins) || topology === false;
  if (analysis && typeof Module.solveSceneWith !== 'function') {
    throw new PdesurfError('Load', 'this solver module has no analysis (solveSceneWith): rebuild the wasm module');
  }
  let res;
  try {
    res = analysis
      ? Module.solveSceneWith(text, nu, nv, {
        curvature: Boolean(curvature), joins: Boolean(joins), crossings: Boolean(crossings), topology: topology !== false,
      })
      : Module.solveScene(text, nu, nv);
  } catch (err) {
    // Should not happen (the binding catches), but never let a raw throw escape.
    const msg = err instanceof Error ? err.message : `solver threw ${String(err)}`;
    throw new PdesurfError('Internal', msg);
  }
  if (!res || typeof res !== 'object') throw new PdesurfError('Internal', 'solver returned no result');
  if (!res.ok) {
    const e = res.error || {};
    throw new PdesurfError(String(e.code || 'Internal'), String(e.message || 'unknown solver error'));
  }
  const out = { patches: Array.from(res.patches || [], normalisePatch) };
  if (joins) {
    out.report = normaliseReport(res.report);
    if (!out.report) throw new PdesurfError('Internal', 'the solver returned no join report');
  }
  return out;
}

// The binding already returns copies (slices of the wasm heap), so the arrays are
// owned here; only check their types.
function normalisePatch(p) {
  const typed = (a, Type, what) => {
    if (!(a instanceof Type)) throw new PdesurfError('Internal', `patch ${p.name}: ${what} is not a ${Type.name}`);
    return a;
  };
  const out = {
    name: String(p.name),
    kind: String(p.kind),
    positions: typed(p.positions, Float32Array, 'positions'),
    normals: typed(p.normals, Float32Array, 'normals'),
  };
  if (p.uvs !== undefined) {
    out.uvs = typed(p.uvs, Float32Array, 'uvs');
    out.indices = typed(p.indices, Uint32Array, 'indices');
  }
  if (p.meanCurvature !== undefined) {
    // Mean H (signed with respect to the drawn normal) and Gaussian K per vertex; 0 where degenerate.
    out.meanCurvature = typed(p.meanCurvature, Float32Array, 'meanCurvature');
    out.gaussCurvature = typed(p.gaussCurvature, Float32Array, 'gaussCurvature');
    out.degenerateVertices = Number(p.degenerateVertices);
  }
  // Version 4: the patches its conditions come from; whether the module re-used its last solve.
  if (p.dependsOn !== undefined) out.dependsOn = Array.from(p.dependsOn, String);
  if (p.reused !== undefined) out.reused = Boolean(p.reused);
  if (p.operator) {
    // Per coordinate: { order, params: { name: value } } with the scene's own names.
    out.operator = {};
    for (const axis of ['x', 'y', 'z']) {
      const c = p.operator[axis];
      const params = {};
      for (const [k, v] of Object.entries(c.params)) params[k] = Number(v);
      out.operator[axis] = { order: Number(c.order), params };
    }
    out.method = String(p.method);
    out.methods = Array.from(p.methods || [], String);
  }
  if (p.ends) {
    // Scene version 3: ends given by reference, with their derived conditions as text.
    out.ends = {};
    for (const end of ['u0', 'u1']) {
      const e = p.ends[end];
      if (!e) continue;
      // Version 4, a chained end: its conditions come from the patch it continues.
      if (e.patch !== undefined) {
        out.ends[end] = { patch: String(e.patch), at: String(e.at) };
        continue;
      }
      const derived = {};
      for (const axis of ['x', 'y', 'z']) derived[axis] = Array.from(e.derived[axis] || [], String);
      out.ends[end] = { surface: String(e.surface), derived };
    }
  }
  if (out.kind === 'bezier') {
    // Variational Bézier patch: solved and initial nets (row-major, 3 per point), the
    // guiding normals as arrows on the solved surface, and the solve's numbers.
    out.netSize = Array.from(p.netSize || [], Number);
    if (out.netSize.length !== 2) throw new PdesurfError('Internal', `patch ${p.name}: netSize is not [rows, cols]`);
    // The nets in doubles (a detached border is typed from them exactly); drawn as float32.
    out.controlNet = typed(p.controlNet, Float64Array, 'controlNet');
    out.initialNet = typed(p.initialNet, Float64Array, 'initialNet');
    out.normalOrigins = typed(p.normalOrigins, Float32Array, 'normalOrigins');
    out.normalVectors = typed(p.normalVectors, Float32Array, 'normalVectors');
    for (const key of ['energy', 'normalMisfit', 'lambda', 'gamma']) out[key] = Number(p[key]);
  }
  return out;
}
