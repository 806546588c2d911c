// One slider per scene parameter, bound straight to scene.parameters[name].value so
// the scene object stays the single source of truth.
import { escapeHtml } from './html-text.js';

/** Build the "Parameters" folder; onChange() is called after each move. */
export function buildParameterFolder(gui, scene, onChange) {
  const folder = gui.addFolder('Parameters');
  const params = scene && scene.parameters && typeof scene.parameters === 'object' ? scene.parameters : {};
  let count = 0;
  for (const [name, p] of Object.entries(params)) {
    if (!p || typeof p !== 'object') continue;
    const { min, max, value } = p;
    // Only plain numeric ranges make a slider; the solver reports anything else.
    if (![min, max, value].every(Number.isFinite) || !(max > min)) continue;
    const ctrl = folder
      .add(p, 'value', min, max, (max - min) / 1000)
      .name(escapeHtml(name))
      .onChange(onChange);
    ctrl.domElement.dataset.param = name; // stable hook for tests and styling
    if (typeof p.label === 'string') ctrl.domElement.title = p.label; // attribute: never parsed
    count++;
  }
  if (count === 0) folder.hide();
  return folder;
}
