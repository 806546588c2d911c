// The B-spline surface the wasm core hands to CAD (cpp/cad/bspline_surface.hpp), as plain
// data: checked here once so a writer can trust it, and its knots in openNURBS's convention.

/** Throws a TypeError naming the first thing wrong with surface `s`; returns `s`. */
export function checkSurface(s) {
  const fail = (what) => { throw new TypeError(`surface ${JSON.stringify(s?.name)}: ${what}`); };
  if (typeof s?.name !== 'string') fail('no name');
  for (const dir of ['U', 'V']) {
    const degree = s[`degree${dir}`], count = s[`count${dir}`], knots = s[`knots${dir}`];
    if (!Number.isInteger(degree) || degree < 1) fail(`degree${dir} ${degree}`);
    if (!Number.isInteger(count) || count <= degree) fail(`count${dir} ${count} for degree ${degree}`);
    if (knots?.length !== count + degree + 1) fail(`knots${dir} has ${knots?.length} knots, not ${count + degree + 1}`);
    for (let k = 0; k < knots.length; k++) {
      if (!Number.isFinite(knots[k]) || (k > 0 && knots[k] < knots[k - 1])) fail(`knots${dir} not finite and non-decreasing at ${k}`);
    }
    // Clamped: the ends repeated degree+1 times, so the surface interpolates its corner poles.
    for (let k = 1; k <= degree; k++) {
      if (knots[k] !== knots[0] || knots.at(-1 - k) !== knots.at(-1)) fail(`knots${dir} not clamped`);
    }
    if (!(knots[0] < knots.at(-1))) fail(`knots${dir} span an empty domain`);
  }
  if (s.poles?.length !== s.countU * s.countV * 3) fail(`${s.poles?.length} pole coordinates, not ${s.countU * s.countV * 3}`);
  for (let k = 0; k < s.poles.length; k++) if (!Number.isFinite(s.poles[k])) fail(`pole coordinate ${k} not finite`);
  return s;
}

/**
 * openNURBS stores no superfluous end knots: the full clamped vector of count+degree+1 knots
 * becomes its count+degree-1 inner ones (same values, so the same domain).
 */
export const openNurbsKnots = (knots) => Array.from(knots).slice(1, -1);
