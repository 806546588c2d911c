// The conditions the solver derived for one end given by reference, read-only: a text
// field per coordinate and derivative (x(0), xᵤ(0), …) in a "derived (read-only)" folder,
// refreshed after every solve and rebuilt when their count changes (tangency → curvature).
// Read-only rather than disabled: the text can still be scrolled, selected and copied, and
// its tooltip (the whole text) shows (lil-gui gives disabled controllers no pointer events).
// DOM hooks: data-derived="<axis>.<k>" on each field.
import { escapeHtml } from './html-text.js';
import { AXES } from '../state/expression-edit.js';

const PRIMES = ['', 'ᵤ', 'ᵤᵤ', 'ᵤᵤᵤ'];

/** Add the folder to `parent` for end 'u0' | 'u1' of a blend meeting `surface`. Returns { show(derived | null) }. */
export function buildDerivedFields(parent, { end, surface }) {
  const box = parent.addFolder(escapeHtml('derived (read-only)'));
  box.domElement.classList.add('derived-folder');
  box.domElement.title = `The conditions derived from “${surface}”, with the parameters' current values; they follow every solve.`;
  const at = end === 'u0' ? 0 : 1;
  let fields = [];
  let model = {};
  let shape = ''; // the counts per coordinate the fields were built for

  function build(derived) {
    for (const f of fields) f.destroy();
    fields = [];
    model = {};
    if (!derived) return;
    for (const axis of AXES) {
      derived[axis].forEach((_, k) => {
        const id = `${axis}.${k}`;
        model[id] = '';
        const ctrl = box.add(model, id).name(escapeHtml(`${axis}${PRIMES[k] ?? `^(${k})`}(${at})`));
        ctrl.domElement.dataset.derived = id;
        ctrl.domElement.classList.add('derived');
        const input = ctrl.domElement.querySelector('input');
        input.readOnly = true;
        input.spellcheck = false;
        fields.push(ctrl);
      });
    }
  }

  return {
    /** The solver's { x: [X, X_u, …], y, z } texts for this end (null: none yet). */
    show(derived) {
      const next = derived ? AXES.map((axis) => derived[axis].length).join(',') : '';
      if (next !== shape) {
        shape = next;
        build(derived);
      }
      for (const ctrl of fields) {
        const id = ctrl.domElement.dataset.derived;
        const [axis, k] = id.split('.');
        model[id] = derived[axis][Number(k)];
        ctrl.updateDisplay();
        ctrl.domElement.querySelector('input').title = model[id]; // the whole text, however narrow the field
      }
    },
  };
}
