// The editor, composed (a chunk the page loads once its first surface is on screen,
// main.js): the document and its one door for edits (state/document.js), the scene session
// (scene-session.js: openings, solves, drawing), the page's chrome (toolbar, layout, help)
// and the features, each subscribing to the document's signals: panel, edits, history,
// Bézier editing, share, files, building, analysis.
import { createPanelWiring } from './panel-wiring.js';
import { createDocument } from './state/document.js';
import { subscribeToEdits } from './edit-subscribers.js';
import { createGallery } from './ui/gallery.js';
import { createToolbar } from './ui/toolbar.js';
import { createLayout } from './ui/layout.js';
import { createHelpOverlay } from './ui/help-overlay.js';
import { watchNumberControls } from './ui/number-access.js';
import { installShortcuts } from './keyboard-shortcuts.js';
import { createSceneState } from './state/scene-state.js';
import { edits } from './state/edits.js';
import { createShareWiring } from './share-wiring.js';
import { createAnalysisWiring } from './analysis-wiring.js';
import { createFileWiring } from './file-wiring.js';
import { createHistoryWiring } from './history-wiring.js';
import { createBuildWiring } from './build-wiring.js';
import { createSceneSession } from './scene-session.js';

/**
 * What the page made first (main.js): { examples (the catalogue), solver and relay (its
 * results reach the session through it), viewer, bezier (bezier-wiring.js), status, hooks,
 * titleEl, fail(err), onAnalysis(analysis): the analysis wiring, for the test hooks }. Opens
 * the scene the page's hash names; resolves once it is opened.
 */
export async function startEditor({ examples, solver, relay, viewer, bezier, status, hooks, titleEl, fail, onAnalysis }) {
  const toolbar = createToolbar(document.getElementById('toolbar'));
  const layout = createLayout();
  const help = createHelpOverlay();
  const state = createSceneState();
  hooks.sceneText = () => state.text();
  const doc = createDocument(state);
  let share = null;
  const panel = createPanelWiring({ doc, share: () => share, bezier });
  let session = null;
  const gallery = createGallery(document.getElementById('gallery'), examples, (id) => session.openExample(id), layout);
  session = createSceneSession({ doc, solver, relay, viewer, panel, gallery, status, hooks, titleEl, examples, fail });
  // For scripts/bench-page.mjs: a grid past the panel's 256 (the page path at 1024²).
  hooks.requestGrid = (nu, nv) => doc.apply(edits.setGrid({ nu, nv }));
  subscribeToEdits(doc, { panel, status, scheduler: session.scheduler });
  doc.on('opened', () => viewer.resetOverlays());

  watchNumberControls(panel.gui);
  // At small sizes the panel is a sheet: its title bar closes it rather than folding it.
  panel.gui.$title.addEventListener('click', () => {
    if (panel.gui._closed && layout.isCompact()) {
      panel.gui.open();
      layout.showPanel(false);
    }
  });
  const undoRedo = createHistoryWiring({
    hooks, restore: session.restoreScene, camera: () => viewer.getCamera(),
    read: () => ({ sceneText: state.text(), grid: { ...state.grid }, exampleId: state.exampleId, title: titleEl.textContent }),
  });
  addToolbarButtons({ toolbar, layout, help, viewer, undoRedo });
  // An edit the solver judges is a step only once it is kept.
  doc.on('judging', () => undoRedo.hold());
  doc.on('judged', (kept) => undoRedo.release(kept));
  installShortcuts({ fit: () => viewer.fit(true), help, layout });

  bezier.connect({ state, viewer, panel, doc, status });
  share = createShareWiring({ viewer, panel, status, hooks });
  const files = createFileWiring({ panel, viewer, state, status, hooks, solver, showScene: session.showScene,
    currentTitle: () => titleEl.textContent, setNotice: session.setNotice });
  createBuildWiring({ doc, panel, viewer, hooks, openBuilt: session.openBuilt });
  const analysis = createAnalysisWiring({ doc, panel, viewer, hasAnalysis: true, requestSolve: session.requestQuiet });
  onAnalysis(analysis);
  session.attach({ share, files, history: undoRedo, solveOptions: () => analysis.solveOptions() });
  await session.openFromHash();
}

function addToolbarButtons({ toolbar, layout, help, viewer, undoRedo }) {
  toolbar.add({ action: 'gallery', label: '☰ Examples', title: 'Examples', group: 'layout', onClick: () => layout.toggleGallery() });
  toolbar.add({ action: 'panel', label: '⚙ Controls', title: 'Controls', group: 'layout', onClick: () => layout.togglePanel() });
  undoRedo.addButtons(toolbar);
  toolbar.add({ action: 'fit', label: '⤢', title: 'Fit the view to every patch (F)', group: 'view', onClick: () => viewer.fit(true) });
  toolbar.add({ action: 'help', label: '?', title: 'Keys, gestures and docs (?)', group: 'help', onClick: () => help.toggle() });
  const mark = () => {
    toolbar.button('gallery').setAttribute('aria-pressed', String(layout.galleryShown()));
    toolbar.button('panel').setAttribute('aria-pressed', String(layout.panelShown()));
  };
  layout.onChange(mark);
  mark();
}
