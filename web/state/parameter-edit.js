// Adding and removing scene parameters. A new parameter gets a range around its
// value; removing one that an expression still uses is allowed on purpose: the
// solver then names the expression, which tells the user what depends on it.

// Names an expression already gives a meaning to (docs/scene-format-v2.md).
const RESERVED = new Set(['pi', 'e', 'u', 'v', 't', 'general', 'sqrt', 'exp', 'log', 'sin', 'cos', 'tan',
  'asin', 'acos', 'atan', 'sinh', 'cosh', 'tanh', 'abs', 'sign']);
const NAME = /^[A-Za-z_][A-Za-z0-9_]*$/;
const MAX_NAME = 64;

const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

/** A slider range around `value`: ± max(1, |value|), so both signs and 0 stay near. */
export function defaultRange(value) {
  const span = Math.max(1, Math.abs(value));
  return [value - span, value + span];
}

/** Why `name` cannot be a new parameter of `scene`, or null if it can. */
export function parameterNameProblem(scene, name) {
  if (typeof name !== 'string' || name === '') return 'a parameter needs a name';
  if (name.length > MAX_NAME) return `a parameter name has at most ${MAX_NAME} characters`;
  if (!NAME.test(name)) return `"${name}" is not a name (letters, digits and _, not starting with a digit)`;
  // Assigning "__proto__" would change the object's prototype instead of adding a key.
  if (name === '__proto__') return `"${name}" is reserved`;
  if (RESERVED.has(name)) return `"${name}" is already a constant, variable or function in expressions`;
  if (isObject(scene.parameters) && Object.hasOwn(scene.parameters, name)) return `there is already a parameter "${name}"`;
  return null;
}

/** Add { value, min, max } under `name`; throws an Error with a readable message. */
export function addParameter(scene, name, value) {
  const problem = parameterNameProblem(scene, name);
  if (problem) throw new Error(problem);
  if (!Number.isFinite(value)) throw new Error(`the value of "${name}" must be a finite number`);
  const [min, max] = defaultRange(value);
  if (!isObject(scene.parameters)) scene.parameters = {};
  scene.parameters[name] = { value, min, max };
  return scene.parameters[name];
}

/** Remove a parameter; the scene keeps an empty "parameters" object if it was the last. */
/** A slider's move: the parameter's value (finite; the slider keeps it in its range). */
export function setParameterValue(scene, name, value) {
  if (!isObject(scene.parameters) || !Object.hasOwn(scene.parameters, name) || !isObject(scene.parameters[name])) {
    throw new Error(`there is no parameter "${name}"`);
  }
  if (!Number.isFinite(value)) throw new Error(`the value of "${name}" must be a finite number`);
  scene.parameters[name].value = value;
}

export function removeParameter(scene, name) {
  if (!isObject(scene.parameters) || !Object.hasOwn(scene.parameters, name)) {
    throw new Error(`there is no parameter "${name}"`);
  }
  delete scene.parameters[name];
}
