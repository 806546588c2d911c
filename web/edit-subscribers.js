// What every edit through the document's door (web/state/document.js) sets off, in one
// place: the re-solve (at once, or once typing pauses), the panel's folders when the scene
// changed shape, and the message of a refused edit. The undo step and the link follow the
// solve (web/scene-session.js: solveNow and applyResult).
import { messageOf } from './state/document.js';

export const EXPRESSION_DEBOUNCE_MS = 150; // typing re-solves once the keys pause

export function subscribeToEdits(doc, { panel, status, scheduler }) {
  let typingTimer = 0;
  doc.on('changed', (edit) => {
    if (edit.structure) panel.restoreScene(doc.state.scene); // folders rebuilt by the next solve
    else panel.showParameterValues();
    panel.refreshGrid();
    if (edit.ends) panel.rebuildEnds();
    const solve = edit.solve || 'now';
    clearTimeout(typingTimer);
    if (solve === 'typed') typingTimer = setTimeout(() => scheduler.request(), EXPRESSION_DEBOUNCE_MS);
    else if (solve === 'now') scheduler.request();
  });
  doc.on('refused', (err, edit) => status.error(`cannot ${edit.name}: ${messageOf(err)}`));
  // A checked edit the solver refused: the scene is back as it was; draw and show it again.
  doc.on('reverted', () => {
    panel.restoreScene(doc.state.scene);
    scheduler.request();
  });
}
