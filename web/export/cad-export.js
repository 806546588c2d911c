// The File folder's CAD exports (docs/page-files.md): every patch of the page's scene as a
// certified B-spline face, fitted in the solver's worker (solver/solver-client.js exportCad,
// never on this thread) and written there as STEP or IGES text by the core, or handed to
// rhino3dm in a worker of its own for a .3dm file (web/cad/export-3dm.js, imported on the
// first .3dm export). This module loads on the first CAD click; the tolerance is checked
// before anything else is sent or fetched.

export const CAD_FORMATS = {
  step: { label: 'STEP', ext: 'step', type: 'model/step' },
  iges: { label: 'IGES', ext: 'igs', type: 'model/iges' },
  '3dm': { label: '3dm', ext: '3dm', type: 'application/octet-stream' },
};

const NUMBER = /^\+?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i; // no hex, no Infinity, no blanks inside
const SHOWN_CHARS = 40; // of a refused tolerance's text, in the message

const invalid = (message) => Object.assign(new Error(message), { code: 'InvalidField' });

/**
 * The tolerance field's text -> a positive finite number (absolute, scene units), or
 * undefined for the core's default (1e-6 of the scene's diagonal) when it is blank; anything
 * else throws an InvalidField Error saying what is wanted.
 */
export function parseTolerance(text) {
  const t = String(text ?? '').trim();
  if (t === '') return undefined;
  const x = NUMBER.test(t) ? Number(t) : NaN;
  if (x > 0 && Number.isFinite(x)) return x;
  const shown = t.length > SHOWN_CHARS ? `${t.slice(0, SHOWN_CHARS)}…` : t;
  throw invalid(`tolerance "${shown}": a positive number in scene units (e.g. 1e-4), or empty for the default (1e-6 of the scene's diagonal)`);
}

/**
 * One CAD file of the scene. solver: the page's solver client; sceneText: the scene as the
 * solver sees it; format: 'step' | 'iges' | '3dm'; tolerance: a number or undefined (the
 * default); base: the file name's base (export/file-names.js).
 * Returns { data (text or bytes), name, type, fit: { title, tolerance, faces, ms } }.
 */
export async function cadFile({ solver, sceneText, format, tolerance, base, onProgress }) {
  const f = CAD_FORMATS[format];
  if (!f) throw invalid(`no CAD format ${JSON.stringify(format)}`);
  const fit = await solver.exportCad(sceneText, { format, tolerance }, { onProgress });
  let data = fit.text;
  if (format === '3dm') {
    const { export3dm } = await import('../cad/export-3dm.js');
    data = await export3dm(fit.faces, { tolerance: fit.tolerance, title: fit.title, breps: fit.breps, archive: fit.archive });
  }
  return { data, name: `${base}.${f.ext}`, type: f.type, fit };
}

// 2 significant digits: 5.3e-6, 0.012, 0
const sci = (x) => (x === 0 ? '0' : Math.abs(x) >= 1e-3 && Math.abs(x) < 1e4 ? String(Number(x.toPrecision(2))) : x.toExponential(1));
const degrees = (x) => `${Number(x.toPrecision(2))}°`;

/**
 * What the fit achieved, as one line of text: "STEP: 3 faces, certified within 5.3e-6
 * (tolerance 8.2e-6)", then the patches whose normals at the ends missed the 0.01° target
 * (a target, not a promise: docs/cad-export.md), then the joins between the faces that are
 * off theirs. { text, missed (names), joinsOff (count) }.
 */
export function fitSummary(format, { tolerance, faces, joins = [] }) {
  const n = faces.length;
  const worst = faces.reduce((m, f) => Math.max(m, f.deviation), 0);
  const exact = faces.filter((f) => f.exact).length;
  let text = `${CAD_FORMATS[format].label}: ${n} face${n === 1 ? '' : 's'}${exact ? ` (${exact} exact)` : ''}, certified within ${sci(worst)} (tolerance ${sci(tolerance)})`;
  const missed = faces.filter((f) => !f.normalsMet);
  if (missed.length) {
    text += `; normals at the ends of ${missed.map((f) => `${f.name} within ${degrees(f.normalDeviationDeg)}`).join(', ')} (target 0.01° not reached)`;
  }
  // The joins between the faces (the join certificate read on the fitted faces): named, as the
  // normals are, only when one is off its target; hooks.lastFile keeps every figure.
  const off = joins.filter((j) => !j.ok);
  if (off.length) {
    text += `; joins off their target: ${off.map((j) => `${j.patch} ${j.end} – ${j.surface} (gap ${sci(j.gap)}, normals ${degrees(j.normalDeg)})`).join(', ')}`;
  }
  return { text, missed: missed.map((f) => f.name), joinsOff: off.length };
}

/** The fit's figures for hooks.lastFile (web/test-hooks.js). */
export function fitRecord({ tolerance, faces, joins = [], ms }) {
  return {
    tolerance,
    fitMs: ms,
    joins: joins.map((j) => ({ patch: j.patch, end: j.end, surface: j.surface, level: j.level, gap: j.gap, allowedGap: j.allowedGap, normalDeg: j.normalDeg, ok: j.ok })),
    faces: faces.map((f) => ({ name: f.name, deviation: f.deviation, normalDeviationDeg: f.normalDeviationDeg, normalsMet: f.normalsMet, exact: f.exact })),
  };
}
