// The module's join report (docs/wasm-api.md, solveSceneWith {joins: true}; the keys of
// `pdesurf check --json`, cpp/analysis/report_json.hpp) as plain, checked data in the page's
// own camelCase for the joins panel and the highlights. Pure: unit-tested in tests/js.
// Every string from the scene stays a string; the panel shows it with textContent.

// The side of the blend that joins: "u0", "u1" (the ends u = 0, 1) or "v0", "v1" (the
// edges v = 0, 1 of a Bézier patch); a bare 0 / 1 means u0 / u1.
const SIDES = new Set(['u0', 'u1', 'v0', 'v1']);
function endOf(e) {
  const s = String(e);
  if (SIDES.has(s)) return s;
  return s === '1' ? 'u1' : 'u0';
}

const num = (x) => (x === null || x === undefined ? null : Number(x));
const LEVELS = new Set(['G0', 'G1', 'G2']);

/** null when the module gave no report (an older module, or not asked). */
export function normaliseReport(raw) {
  if (!raw || typeof raw !== 'object') return null;
  const joinOf = (j) => ({
    patch: String(j.patch),
    end: endOf(j.end),
    surface: String(j.surface ?? ''),
    edge: String(j.edge ?? ''),
    level: LEVELS.has(String(j.level)) ? String(j.level) : String(j.level ?? '?'),
    g0: num(j.g0),
    g1Deg: num(j.g1_deg),
    g2Rel: num(j.g2_rel),
    fold: Boolean(j.fold),
    ok: Boolean(j.ok),
    degenerate: Number(j.degenerate) || 0,
    worstV: num(j.worst_v ?? j.worst_u), // where along the join the worst measure is (a seam's: a u)
  });
  const joins = Array.from(raw.joins || [], joinOf);
  // Closed patches joined to themselves across v0 = v1 (a fill, a tube): worstV is the u there.
  const seams = Array.from(raw.seams || [], joinOf);
  const crossings = Array.from(raw.crossings || [], (c) => ({
    patch: String(c.patch),
    other: String(c.other),
    u: Array.from(c.u || [], Number),
    v: Array.from(c.v || [], Number),
    triangles: Number(c.triangles) || 0,
  }));
  // Crossings are checked only when asked ({crossings: true}); a module that predates the
  // option always checked them.
  const crossingsChecked = raw.crossings_checked !== false;
  // Version 4: every fill's centre (analysis/fill_centre.hpp).
  const centres = Array.from(raw.centres || [], (c) => ({
    patch: String(c.patch),
    normalSpreadDeg: num(c.normal_spread_deg),
    normalSpreadOuterDeg: num(c.normal_spread_outer_deg),
    fold: Boolean(c.fold),
    curvatureNear: num(c.curvature_near),
    curvatureRatio: num(c.curvature_ratio),
    ok: Boolean(c.ok),
  }));
  // Issue 36: the model's bodies (the patches the joins connect), closed or open, area, volume.
  const bodies = Array.from(raw.bodies || [], (b) => ({
    patches: Array.from(b.patches || [], String),
    closed: Boolean(b.closed),
    area: num(b.area),
    volume: num(b.volume),
    freeEdges: Number(b.free_edges) || 0,
  }));
  const out = { ok: Boolean(raw.ok), sceneSize: Number(raw.scene_size), joins, seams, crossings, crossingsChecked, centres, bodies };
  // A declared join the module cannot certify: the scene still draws, the report says why.
  if (raw.error) out.error = { code: String(raw.error.code ?? 'Internal'), message: String(raw.error.message ?? '') };
  return out;
}

/** A body as one line of text (no markup): "closed body of 5 patches: area 33.13, volume 14.37" (4 digits). */
export function bodyText(b) {
  const n = `${b.patches.length} ${b.patches.length === 1 ? 'patch' : 'patches'}`;
  if (b.closed) return `closed body of ${n}: area ${sig(b.area, 4)}, volume ${sig(b.volume, 4)}`;
  return `open body of ${n} (${b.freeEdges} free ${b.freeEdges === 1 ? 'edge' : 'edges'}): area ${sig(b.area, 4)}`;
}

/** A stable key for one join: the blend's name, its end and what it meets (a fill meets several). */
export const joinKey = (j) => `${j.patch}\u0000${j.end}\u0000${j.surface}\u0000${j.edge}`;

/** A closed patch's seam as one line of text (no markup). */
export function seamText(j) {
  const sharp = j.level === 'G0' ? ' (sharp in its data)' : '';
  const angle = j.g1Deg === null || !Number.isFinite(j.g1Deg) ? '—' : `${sig(j.g1Deg)}°`;
  return `“${j.patch}” seam v0 = v1${sharp}: ${j.level}, gap ${sig(j.g0)}, angle ${angle}: ${j.ok ? 'ok' : 'FAILS'}`;
}

/** A fill's centre as one line of text (no markup). */
export function centreText(c) {
  const spread = (x) => (x === null || !Number.isFinite(x) ? '—' : `${x.toPrecision(2)}°`);
  return `“${c.patch}” centre: normal spread ${spread(c.normalSpreadDeg)} (from ${spread(c.normalSpreadOuterDeg)}), ${c.fold ? 'folds' : 'no fold'}, curvature ratio ${c.curvatureRatio === null ? '—' : c.curvatureRatio.toFixed(2)}: ${c.ok ? 'regular' : 'NOT regular'}`;
}

const sig = (x, digits = 2) => {
  if (x === null || !Number.isFinite(x)) return '—';
  if (x === 0) return '0';
  const a = Math.abs(x);
  return a < 1e-3 || a >= 1e4 ? x.toExponential(digits - 1) : Number(x.toPrecision(digits)).toString();
};

/** The measured numbers of one join as short labelled strings (no markup). */
export function joinFigures(j) {
  return [
    ['G0 gap', sig(j.g0)],
    ['G1 angle', j.g1Deg === null ? '—' : `${sig(j.g1Deg)}°`],
    ['G2 mismatch', j.g2Rel === null ? '—' : `${sig(100 * j.g2Rel)} %`],
    ['fold', j.fold ? 'yes' : 'no'],
    ...(j.worstV !== null && Number.isFinite(j.worstV) ? [['worst at v', sig(j.worstV, 3)]] : []),
  ];
}

/** One line per crossing. */
export function crossingText(c) {
  const range = (r) => (r.length === 2 ? `[${sig(r[0], 3)}, ${sig(r[1], 3)}]` : '?');
  return `“${c.patch}” crosses “${c.other}” at u ∈ ${range(c.u)}, v ∈ ${range(c.v)}`;
}

/**
 * Which joins are highlighted: failing ones unless the user unticked them, others when
 * ticked. overrides: Map key -> bool (the user's ticks).
 */
export function highlightedKeys(report, overrides) {
  const out = [];
  for (const j of report ? report.joins : []) {
    const k = joinKey(j);
    const on = overrides.has(k) ? overrides.get(k) : !j.ok;
    if (on) out.push(k);
  }
  return out;
}
