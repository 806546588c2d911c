// The editor, composed (a chunk the page loads once its first surface is on screen,
// main.js): the document and its one door for edits (state/document.js), the scene session
// (scene-session.js: openings, solves, drawing), the page's chrome (toolbar, layout, help)
// and the features (web/features/), each made from one context object and subscribing to the
// document's signals: panel, history, Bézier editing, share, files, building, analysis.
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
import { createSceneSession } from './scene-session.js';
import { createPanelFeature } from './features/panel.js';
import { createShareFeature } from './features/share.js';
import { createAnalysisFeature } from './features/analysis.js';
import { createFilesFeature } from './features/files.js';
import { createHistoryFeature } from './features/history.js';
import { createBuildFeature } from './features/build.js';

/**
 * What the page made first (main.js): { examples (the catalogue), solver and relay (its
 * results reach the session through it), viewer, bezier (features/bezier.js), status, hooks,
 * titleEl, fail(err), onAnalysis(analysis): the analysis feature, for the test hooks }. Opens
 * the scene the page's hash names; resolves once it is opened.
 */
export async function startEditor({ examples, solver, relay, viewer, bezier, status, hooks, titleEl, fail, onAnalysis }) {
  const toolbar = createToolbar(document.getElementById('toolbar'));
  const layout = createLayout();
  const help = createHelpOverlay();
  const state = createSceneState();
  hooks.sceneText = () => state.text();
  const doc = createDocument(state);
  // The context every feature is made from; features made later (share, files, …) join it.
  const ctx = { doc, state, solver, viewer, bezier, status, hooks, titleEl, layout, toolbar };
  ctx.panel = createPanelFeature(ctx);
  const gallery = createGallery(document.getElementById('gallery'), examples, (id) => ctx.session.openExample(id), layout);
  ctx.session = createSceneSession({ doc, solver, relay, viewer, panel: ctx.panel, gallery, status, hooks, titleEl, examples, fail });
  const { panel, session } = ctx;
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
  ctx.history = createHistoryFeature(ctx);
  addToolbarButtons({ toolbar, layout, help, viewer, undoRedo: ctx.history });
  // An edit the solver judges is a step only once it is kept.
  doc.on('judging', () => ctx.history.hold());
  doc.on('judged', (kept) => ctx.history.release(kept));
  installShortcuts({ fit: () => viewer.fit(true), help, layout });

  bezier.connect(ctx);
  ctx.share = createShareFeature(ctx);
  ctx.files = createFilesFeature(ctx);
  createBuildFeature(ctx);
  ctx.analysis = createAnalysisFeature(ctx);
  onAnalysis(ctx.analysis);
  session.attach({ share: ctx.share, files: ctx.files, history: ctx.history, solveOptions: () => ctx.analysis.solveOptions() });
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
