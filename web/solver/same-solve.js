// Whether two solve requests are the same work: the same scene text and the same options in
// any key order (a solve is a function of both). { scene, options } each.
export function sameSolve(a, b) {
  const key = (o) => JSON.stringify(Object.keys(o || {}).sort().map((k) => [k, o[k]]));
  return a.scene === b.scene && key(a.options) === key(b.options);
}
