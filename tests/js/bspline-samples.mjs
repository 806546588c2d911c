// Surfaces of the shape the wasm core hands to CAD (web/cad/bspline-surface.js), for the .3dm
// writer's tests: an open cubic, a quintic on non-uniform knots, a tube closed in v, and a
// surface with its u0 border collapsed to a point. Seeded, so every run writes the same.

/** A seeded generator of uniform numbers in [0, 1) (mulberry32). */
export function random(seed) {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** A clamped knot vector on [a, b] with the given interior knots. */
export const clamped = (degree, a, b, interior = []) =>
  [...Array(degree + 1).fill(a), ...interior, ...Array(degree + 1).fill(b)];

/** Uniform interior knots for `count` poles of `degree` on [a, b]. */
export const uniform = (degree, count, a, b) =>
  clamped(degree, a, b, Array.from({ length: count - degree - 1 }, (_, k) => a + ((b - a) * (k + 1)) / (count - degree)));

function surface(name, degreeU, degreeV, knotsU, knotsV, pole, extra = {}) {
  const countU = knotsU.length - degreeU - 1, countV = knotsV.length - degreeV - 1;
  const poles = new Float64Array(countU * countV * 3);
  for (let i = 0; i < countU; i++) for (let j = 0; j < countV; j++) poles.set(pole(i, j, countU, countV), (i * countV + j) * 3);
  return { name, degreeU, degreeV, countU, countV, knotsU, knotsV, poles, closedV: false,
    degenerate: [false, false, false, false], deviation: 1e-7, ...extra };
}

/** The four sample surfaces; `rnd` jitters the poles. */
export function samples(rnd = random(1)) {
  const j = (scale) => (rnd() - 0.5) * scale;
  return [
    // A height field over a grid, in its own (u, v) = [0.5, 2.5] x [-1, 3].
    surface('open cubic', 3, 3, uniform(3, 6, 0.5, 2.5), uniform(3, 7, -1, 3),
      (i, k) => [i * 10, k * 8, 5 * Math.sin(i + k) + j(2)]),
    // Quintic both ways on uneven knots, a double interior knot in v, far from the origin.
    surface('blend', 5, 5, clamped(5, 0, 1, [0.05, 0.3, 0.31, 0.7]), clamped(5, 2, 7, [2.2, 4, 4, 6.5]),
      (i, k) => [1000 + i * 12 + j(3), -500 + k * 9 + j(3), 250 + 20 * Math.cos(i * k) + j(3)]),
    // A tube: v runs round the circle, the last pole column equal to the first (closedV).
    surface('tube', 3, 3, uniform(3, 5, 0, 1), uniform(3, 9, 0, 1), (i, k, nu, nv) => {
      const a = (2 * Math.PI * (k % (nv - 1))) / (nv - 1), r = 20 + 3 * Math.sin(i);
      return [r * Math.cos(a), r * Math.sin(a), i * 15];
    }, { closedV: true }),
    // A cone-like fill: every pole of the u0 border at one apex.
    surface('apex', 3, 4, uniform(3, 6, 0, 1), uniform(4, 8, 0, 2), (i, k, nu, nv) => {
      const a = (2 * Math.PI * k) / (nv - 1), r = 4 * i;
      return i === 0 ? [0, 0, 30] : [r * Math.cos(a) + j(1), r * Math.sin(a) + j(1), 30 - 5 * i];
    }, { degenerate: [true, false, false, false] }),
  ];
}

/** A square-ish surface of n x n poles (cubic), for timing writes. */
export const grid = (name, n, rnd = random(7)) =>
  surface(name, 3, 3, uniform(3, n, 0, 1), uniform(3, n, 0, 1), (i, k) => [i, k, rnd()]);
