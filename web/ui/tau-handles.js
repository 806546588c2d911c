// "τ by values": a curve trimline shaped by five sliders, the trimline's t at five equally
// spaced v along the border; the page turns them into the trigonometric sum through them
// (web/state/trig-curve.js, 2 harmonics: 5 values, exact), so the blend stays closed form
// where the surface allows. The sliders start at the current τ(v) and span the surface's
// t_range; moving one rewrites τ(v) (one edit through the end's handler).
import { escapeHtml } from './html-text.js';
import { compile, parameterValues } from '../state/expr-text.js';
import { trigCurveFromSamples } from '../state/trig-curve.js';

export const HANDLES = 5;

const numberOf = (x, params) => (typeof x === 'number' ? x : compile(String(x), params)({}));

// Where the fitted sum leaves [t0, t1] on a fine sampling of the range, or null.
function outside({ a0, a, b, omega }, v0, v1, t0, t1) {
  const n = 720;
  let worst = null;
  for (let i = 0; i <= n; i++) {
    const v = v0 + ((v1 - v0) * i) / n;
    let t = a0;
    for (let k = 0; k < a.length; k++) t += a[k] * Math.cos((k + 1) * omega * v) + b[k] * Math.sin((k + 1) * omega * v);
    const by = Math.max(t0 - t, t - t1);
    if (by > 1e-12 * Math.max(1, Math.abs(t0), Math.abs(t1)) && (!worst || by > worst.by)) worst = { v, t, by };
  }
  return worst;
}

/**
 * scene, blend (its pde patch), end ('u0' | 'u1'), tau (its text), onTau(text).
 * Returns the folder, or null when the ranges cannot be evaluated here (the solver says why).
 */
export function buildTauHandles(parent, { scene, blend, end, tau, onTau }) {
  const surfaceName = blend?.ends?.[end]?.surface;
  const surface = (scene?.patches || []).find((p) => p && p.name === surfaceName);
  if (!surface) return null;
  let t0, t1, v0, v1, at;
  try {
    const params = parameterValues(scene);
    [t0, t1] = (surface.t_range || [0, 1]).map((x) => numberOf(x, params));
    [v0, v1] = (blend.v_range || [0, '2*pi']).map((x) => numberOf(x, params));
    const f = compile(String(tau), params, ['v']);
    at = (v) => f({ v });
  } catch {
    return null;
  }
  if (![t0, t1, v0, v1].every(Number.isFinite) || !(t1 > t0) || !(v1 > v0)) return null;
  const folder = parent.addFolder(escapeHtml('τ by values'));
  folder.domElement.dataset.endField = 'tau-values';
  const values = {};
  // The curve through the values may swing outside the surface's t_range between them: said
  // here, and not sent (the solver would refuse it; the last good blend stays).
  const note = document.createElement('div');
  note.className = 'end-note tau-values-note';
  note.setAttribute('role', 'status');
  const vs = Array.from({ length: HANDLES }, (_, k) => v0 + (k * (v1 - v0)) / HANDLES);
  const step = (t1 - t0) / 1000;
  vs.forEach((v, k) => {
    const start = at(v);
    values[k] = Number.isFinite(start) ? Math.min(t1, Math.max(t0, start)) : (t0 + t1) / 2;
    folder.add(values, String(k), t0, t1, step).name(escapeHtml(`t at v = ${v.toFixed(2)}`)).onChange(() => {
      const fit = trigCurveFromSamples(vs.map((_, j) => values[j]), [v0, v1], 2);
      const out = outside(fit, v0, v1, t0, t1);
      note.textContent = out
        ? `the curve through these values reaches t = ${out.t.toPrecision(4)} at v = ${out.v.toFixed(2)}, outside [${t0.toPrecision(4)}, ${t1.toPrecision(4)}]: move the values near it`
        : '';
      if (!out) onTau(fit.text);
    });
  });
  folder.$children.append(note);
  folder.close();
  return folder;
}
