// The panel's "Build" folder: a new scene, the Add menu (the surface library), a blend
// between two borders and a fill of a loop of four — each as choices (keyboard and touch)
// or picked in the view. It only reports what the user asked; web/features/build.js makes the
// edits through the document's door. Every text shown comes from the scene or the solver
// and is set as text, never as markup.
import { SURFACE_LIBRARY } from '../state/surface-library.js';
import { escapeHtml } from './html-text.js';

const CONTINUITIES = { 'position (G0)': 'position', 'tangency (G1)': 'tangency', 'curvature (G2)': 'curvature' };
export const NONE = '—';

// "0, 2*pi" -> [0, "2*pi"]: two entries, plain numbers as numbers.
function rangeOf(text, name) {
  const parts = String(text).split(',').map((p) => p.trim());
  if (parts.length !== 2 || parts.some((p) => p === '')) throw new Error(`${name} range: expected "from, to", not ${JSON.stringify(String(text))}`);
  return parts.map((p) => (Number.isFinite(Number(p)) ? Number(p) : p));
}

const borderLabel = (b) => `${b.surface} · ${b.at}`;
// lil-gui writes option names as markup: a name from the scene is escaped to show as text.
const asOptions = (labels) => Object.fromEntries(labels.map((l) => [escapeHtml(l), l]));

/**
 * handlers: { onNew(), onAdd(kindId, options?), onBlend(a, b, options), onFill(borders, { kind: 'bezier' | 'pde', continuity }),
 *   onPickMode(kind: 'blend' | 'fill' | null) }; borders are { surface, at }.
 */
export function buildBuildFolder(gui, handlers) {
  const folder = gui.addFolder('Build');
  folder.domElement.classList.add('build-folder');
  const add = { kind: SURFACE_LIBRARY[0].id };
  const labels = Object.fromEntries(SURFACE_LIBRARY.map((e) => [escapeHtml(e.label), e.id]));
  folder.add({ new: () => handlers.onNew() }, 'new').name('new empty scene');
  const addRow = folder.add(add, 'kind', labels).name('surface');
  addRow.domElement.dataset.build = 'kind';
  folder.add({ add: () => handlers.onAdd(add.kind) }, 'add').name('+ add surface');
  // A surface typed as three expressions in t and v, with its ranges.
  const custom = folder.addFolder('Custom surface');
  const typed = { x: 'cos(v)', y: 'sin(v)', z: 't', t: '0, 1', v: '0, 2*pi' };
  for (const [key, label] of [['x', 'x(t,v)'], ['y', 'y(t,v)'], ['z', 'z(t,v)'], ['t', 't from, to'], ['v', 'v from, to']]) {
    custom.add(typed, key).name(escapeHtml(label)).domElement.dataset.build = `custom-${key}`;
  }
  custom.add({ add: () => {
    let ranges;
    try {
      ranges = { t_range: rangeOf(typed.t, 't'), v_range: rangeOf(typed.v, 'v') };
    } catch (err) {
      say(`cannot add a custom surface: ${err.message}`, true);
      return;
    }
    handlers.onAdd('custom', { x: typed.x, y: typed.y, z: typed.z, ...ranges });
  } }, 'add').name('+ add custom surface');
  custom.close();

  const draft = { a: NONE, b: NONE, continuity: 'tangency', power: 1, pick: false };
  // The fill's kind: a Bézier patch (four borders, seed 002) or a PDE fill (1 to 8 borders,
  // G1 to each, a regular centre; docs/chains-and-fills.md).
  const FILL_KINDS = { 'Bézier (4 borders)': 'bezier', 'PDE (1–8 borders)': 'pde' };
  const SLOTS = ['b0', 'b1', 'b2', 'b3', 'b4', 'b5', 'b6', 'b7'];
  const fillDraft = { kind: 'bezier', continuity: 'tangency', pick: false, ...Object.fromEntries(SLOTS.map((k) => [k, NONE])) };
  const slotsOf = () => (fillDraft.kind === 'pde' ? SLOTS : SLOTS.slice(0, 4));
  let choices = [NONE];
  let byLabel = new Map();
  let blend = null;
  let fill = null;

  // Rebuilt whenever the borders on offer change (lil-gui's options() would move the row).
  function buildChoices() {
    const wasOpen = [blend ? !blend._closed : true, fill ? !fill._closed : false];
    blend?.destroy();
    fill?.destroy();
    blend = folder.addFolder('Blend two borders');
    blend.add(draft, 'a', asOptions(choices)).name('from').domElement.dataset.build = 'blend-a';
    blend.add(draft, 'b', asOptions(choices)).name('to').domElement.dataset.build = 'blend-b';
    blend.add(draft, 'continuity', CONTINUITIES).name('continuity').domElement.dataset.build = 'blend-continuity';
    blend.add(draft, 'power', 0.1, 4, 0.01).name('power');
    blend.add(draft, 'pick').name('pick in the view').onChange((on) => setPick(on ? 'blend' : null)).domElement.dataset.build = 'blend-pick';
    blend.add({ make: () => makeBlend() }, 'make').name('make the blend').domElement.dataset.build = 'blend-make';
    fill = folder.addFolder('Fill a loop of borders');
    fill.add(fillDraft, 'kind', FILL_KINDS).name('fill').onChange(() => buildChoices()).domElement.dataset.build = 'fill-kind';
    // A PDE fill meets its borders with tangency (G1) or curvature (G2); position (G0) too.
    if (fillDraft.kind === 'pde') fill.add(fillDraft, 'continuity', CONTINUITIES).name('continuity').domElement.dataset.build = 'fill-continuity';
    slotsOf().forEach((k, i) => {
      fill.add(fillDraft, k, asOptions(choices)).name(`border ${i + 1}`).domElement.dataset.build = `fill-${i}`;
    });
    fill.add(fillDraft, 'pick').name('pick in the view').onChange((on) => setPick(on ? 'fill' : null)).domElement.dataset.build = 'fill-pick';
    fill.add({ make: () => makeFill() }, 'make').name('fill the loop').domElement.dataset.build = 'fill-make';
    if (!wasOpen[0]) blend.close();
    if (!wasOpen[1]) fill.close();
    folder.$children.append(message); // the answer stays last
  }

  // The answer to the last build request: the core's named error, or what was made.
  const message = document.createElement('div');
  message.className = 'build-message';
  message.setAttribute('role', 'status');
  folder.$children.append(message);
  buildChoices();

  function setPick(kind) {
    draft.pick = kind === 'blend';
    fillDraft.pick = kind === 'fill';
    refresh();
    handlers.onPickMode(kind);
  }

  const chosen = (label) => (label === NONE ? null : byLabel.get(label));

  function makeBlend() {
    const a = chosen(draft.a), b = chosen(draft.b);
    if (!a || !b) return say('choose the two borders to blend (or pick them in the view)', true);
    handlers.onBlend(a, b, { continuity: draft.continuity, power: draft.power });
  }

  function makeFill() {
    if (fillDraft.kind === 'pde') {
      const borders = SLOTS.map((k) => chosen(fillDraft[k])).filter(Boolean);
      if (!borders.length) return say('choose the borders around the hole, 1 to 8 (or pick them in the view)', true);
      return handlers.onFill(borders, { kind: 'pde', continuity: fillDraft.continuity });
    }
    const borders = SLOTS.slice(0, 4).map((k) => chosen(fillDraft[k]));
    if (borders.some((b) => !b)) return say('choose the four borders around the hole (or pick them in the view)', true);
    handlers.onFill(borders, { kind: 'bezier' });
  }

  function say(text, error = false) {
    message.textContent = text;
    message.classList.toggle('error', error);
  }

  return {
    folder,
    say,
    setPick,
    /** The scene's surface borders, offered by every border choice. */
    setBorders(borders) {
      byLabel = new Map(borders.map((b) => [borderLabel(b), b]));
      choices = [NONE, ...byLabel.keys()];
      for (const [obj, key] of [[draft, 'a'], [draft, 'b'], ...SLOTS.map((k) => [fillDraft, k])]) {
        if (!byLabel.has(obj[key])) obj[key] = NONE;
      }
      buildChoices();
    },
    /** A border picked in the view fills the next empty choice; returns the choices so far. */
    picked(kind, border) {
      const label = borderLabel(border);
      if (kind === 'blend') {
        if (draft.a === NONE || draft.b !== NONE) {
          draft.a = label;
          draft.b = NONE;
        } else draft.b = label;
        refresh();
        return [chosen(draft.a), chosen(draft.b)].filter(Boolean);
      }
      const keys = slotsOf();
      const free = keys.find((k) => fillDraft[k] === NONE);
      if (!free) {
        keys.forEach((k) => { fillDraft[k] = NONE; });
        fillDraft.b0 = label;
      } else fillDraft[free] = label;
      refresh();
      return keys.map((k) => chosen(fillDraft[k])).filter(Boolean);
    },
    blendOptions: () => ({ continuity: draft.continuity, power: draft.power }),
    /** The fill's kind and how many borders it takes before a pick makes it ('pde': 6, or the button). */
    fillOptions: () => ({ kind: fillDraft.kind, continuity: fillDraft.continuity }),
    /** After a blend or a fill was made (or refused): the choices start again. */
    clearChoices() {
      draft.a = draft.b = NONE;
      for (const k of SLOTS) fillDraft[k] = NONE;
      refresh();
    },
  };

  function refresh() {
    for (const c of folder.controllersRecursive()) c.updateDisplay();
  }
}
