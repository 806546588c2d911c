// Expression texts as the core reads them (cpp/expr/parse.cpp), token by token: which
// names an expression uses, renaming a name, and evaluating an expression without
// variables. Used by the scene-building edits to validate BEFORE they change a scene.

/** Functions of the expression language (docs/scene-format-v2.md). */
export const FUNCTIONS = new Set(['sqrt', 'exp', 'log', 'sin', 'cos', 'tan', 'asin', 'acos', 'atan',
  'sinh', 'cosh', 'tanh', 'abs', 'sign', 'general']);
/** Names the core gives a meaning of its own (scene_json.cpp parseParameters refuses them). */
export const RESERVED = new Set(['pi', 'e', 'u', 'v', 't']);
/** The core's parameter names: a letter or _, then letters, digits or _; at most 32 bytes. */
export const PARAMETER_NAME = /^[A-Za-z_][A-Za-z0-9_]{0,31}$/;

const IDENT = /[A-Za-z_][A-Za-z0-9_]*/y;
// A decimal number as the core scans it (digits, '.', digits, exponent).
const NUMBER = /(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?/y;

/**
 * The tokens of `text`: { kind: 'name' | 'call' | 'number' | 'op', text, at }. A name
 * followed by '(' (spaces allowed) is a function call, as in the core: never a parameter.
 */
export function tokens(text) {
  const s = String(text);
  const out = [];
  let i = 0;
  while (i < s.length) {
    const c = s[i];
    if (/\s/.test(c)) { i++; continue; }
    NUMBER.lastIndex = i;
    IDENT.lastIndex = i;
    let m;
    if (/[0-9.]/.test(c) && (m = NUMBER.exec(s))) {
      out.push({ kind: 'number', text: m[0], at: i });
      i += m[0].length;
    } else if ((m = IDENT.exec(s))) {
      let k = i + m[0].length;
      while (k < s.length && /\s/.test(s[k])) k++;
      out.push({ kind: s[k] === '(' ? 'call' : 'name', text: m[0], at: i });
      i += m[0].length;
    } else {
      out.push({ kind: 'op', text: c, at: i });
      i++;
    }
  }
  return out;
}

/** The set of names (not function calls) an expression text uses. */
export function namesIn(text) {
  return new Set(tokens(text).filter((t) => t.kind === 'name').map((t) => t.text));
}

/**
 * `text` with every name token in `map` replaced by map[name] (parenthesised when the
 * replacement is not a single name or number, so precedence is kept). Calls and the
 * rest of the text are left as they are.
 */
export function replaceNames(text, map) {
  const s = String(text);
  let out = '';
  let last = 0;
  for (const t of tokens(s)) {
    if (t.kind !== 'name' || !Object.hasOwn(map, t.text)) continue;
    const r = String(map[t.text]);
    const simple = /^([A-Za-z_][A-Za-z0-9_]*|\d+\.?\d*)$/.test(r);
    out += s.slice(last, t.at) + (simple ? r : `(${r})`);
    last = t.at + t.text.length;
  }
  return out + s.slice(last);
}

const FN = {
  sqrt: Math.sqrt, exp: Math.exp, log: Math.log, sin: Math.sin, cos: Math.cos, tan: Math.tan,
  asin: Math.asin, acos: Math.acos, atan: Math.atan, sinh: Math.sinh, cosh: Math.cosh, tanh: Math.tanh,
  abs: Math.abs, sign: (x) => (Number.isNaN(x) ? x : Math.sign(x)), general: (x) => x,
};

/**
 * Parse `text` with the core's grammar (sum, product, unary -, right-associative ^ that binds
 * tighter than unary minus) and return a function of the variables (an object such as
 * { t, v }). `params`: { name: value }; `variables`: the names allowed as variables.
 * Throws an Error naming the column, as the core does, for text the core would refuse.
 */
export function compile(text, params = {}, variables = []) {
  const s = String(text);
  if (s.length > 1000) throw new Error('expression longer than 1000 characters');
  const ts = tokens(s);
  let k = 0;
  const col = () => `col ${(ts[k]?.at ?? s.length) + 1}`;
  const fail = (why) => { throw new Error(`${col()}: ${why}`); };
  const peek = (op) => ts[k]?.kind === 'op' && ts[k].text === op;
  const eat = (op) => (peek(op) ? (k++, true) : false);
  let depth = 0;
  const sum = () => {
    let f = product();
    for (;;) {
      if (eat('+')) { const a = f, b = product(); f = (x) => a(x) + b(x); } else if (eat('-')) { const a = f, b = product(); f = (x) => a(x) - b(x); } else return f;
    }
  };
  const product = () => {
    let f = unary();
    for (;;) {
      if (eat('*')) { const a = f, b = unary(); f = (x) => a(x) * b(x); } else if (eat('/')) { const a = f, b = unary(); f = (x) => a(x) / b(x); } else return f;
    }
  };
  const unary = () => {
    if (++depth > 64) fail('expression nested too deeply');
    let f;
    if (eat('-')) { const a = unary(); f = (x) => -a(x); } else if (eat('+')) f = unary();
    else {
      const base = primary();
      if (eat('^')) { const e = unary(); f = (x) => base(x) ** e(x); } else f = base;
    }
    depth--;
    return f;
  };
  const primary = () => {
    const t = ts[k];
    if (!t) fail('expression ends too early');
    if (eat('(')) {
      const f = sum();
      if (!eat(')')) fail("unbalanced '(': missing ')'");
      return f;
    }
    k++;
    if (t.kind === 'number') {
      const next = ts[k];
      if (next && next.at === t.at + t.text.length && (next.kind !== 'op' || next.text === '.')) { k--; fail('bad number: numbers are decimal, such as 16, 0.5 or 1.5e-3'); }
      const value = Number(t.text);
      return () => value;
    }
    if (t.kind === 'call') {
      if (!Object.hasOwn(FN, t.text)) { k--; fail(`unknown function '${t.text}'`); }
      eat('(');
      const a = sum();
      if (!eat(')')) fail("unbalanced '(': missing ')'");
      const g = FN[t.text];
      return (x) => g(a(x));
    }
    if (t.kind === 'name') {
      if (Object.hasOwn(params, t.text)) { const value = params[t.text]; return () => value; }
      if (t.text === 'pi') return () => Math.PI;
      if (t.text === 'e') return () => Math.E;
      if (variables.includes(t.text)) { const name = t.text; return (x) => x[name]; }
      k--;
      if (RESERVED.has(t.text)) fail(`'${t.text}' cannot be used here`);
      fail(`unknown parameter '${t.text}'`);
    }
    k--;
    fail(t.text === ')' ? "unbalanced ')'" : `unexpected '${t.text}'`);
    return null;
  };
  const f = sum();
  if (k < ts.length) fail(ts[k].text === ')' ? "unbalanced ')'" : `unexpected '${ts[k].text}'`);
  return f;
}

/** The scene's parameters as { name: value }. */
export function parameterValues(scene) {
  const out = {};
  const ps = scene?.parameters;
  if (ps && typeof ps === 'object') for (const [name, p] of Object.entries(ps)) out[name] = p?.value;
  return out;
}

/**
 * The value of a number field (a JSON number or an expression over the scene's
 * parameters, no variables). Throws `${path}: …` when the core would refuse it.
 */
export function numberField(scene, value, path) {
  if (typeof value === 'number') {
    if (!Number.isFinite(value)) throw new Error(`${path}: not finite`);
    return value;
  }
  if (typeof value !== 'string') throw new Error(`${path}: expected a number or an expression`);
  let x;
  try {
    x = compile(value, parameterValues(scene))({});
  } catch (err) {
    throw new Error(`${path}: ${err.message}`);
  }
  if (!Number.isFinite(x)) throw new Error(`${path}: '${value}' is not finite`);
  return x;
}

/** Check an expression in `variables` (e.g. ['t', 'v']); throws `${path}: …`. */
export function checkExpression(scene, text, variables, path) {
  if (typeof text !== 'string' && typeof text !== 'number') throw new Error(`${path}: expected an expression`);
  try {
    compile(String(text), parameterValues(scene), variables);
  } catch (err) {
    throw new Error(`${path}: ${err.message}`);
  }
}
