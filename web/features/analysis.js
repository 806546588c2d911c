// Wiring of the surface-quality analysis: the "Analysis" folder (shading mode, wireframe,
// zebra and colour-scale settings), the curvature legend, the "Joins" folder and the join
// highlights in the view. Curvature comes from the module per vertex (solveSceneWith
// {curvature: true}), asked for only while a curvature map is shown; the join report
// ({joins: true}) with every solve, its crossing test ({crossings: true}, several times the
// cost of a re-solve) only while the Joins folder is open. The worker draws first and
// certifies after ('certified'): meanwhile the folder keeps the last report and says
// "checking…". An older module without them still draws: the legend
// and the joins folder say what is missing.
import { buildAnalysisFolder, defaultAnalysisSettings } from '../ui/analysis-controls.js';
import { buildJoinsFolder } from '../ui/joins-panel.js';
import { createCurvatureLegend } from '../ui/curvature-legend.js';
import { curvatureScale } from '../state/curvature-scale.js';
import { highlightedKeys, joinKey } from '../state/join-report.js';

const CURVATURE_KEY = { mean: 'meanCurvature', gauss: 'gaussCurvature' };
const OLD_MODULE = 'this solver module computes no curvature; rebuild it (scripts/build-wasm)';
const NO_REPORT = 'this solver module gives no join report; rebuild it (scripts/build-wasm)';

/** The context's { doc, panel, viewer, session (its requestQuiet re-solves for a new analysis) } */
export function createAnalysisFeature({ doc, panel, viewer, session }) {
  const hasAnalysis = true; // the module has solveSceneWith (an older one: the folders say what is missing)
  const requestSolve = () => session.requestQuiet();
  const settings = defaultAnalysisSettings();
  const controls = buildAnalysisFolder(panel.gui, settings, onChange);
  const joins = buildJoinsFolder(panel.gui, onToggle, onJoinsOpen);
  controls.folder.close();
  joins.folder.close();
  panel.keepAtEnd(controls.folder.domElement, joins.folder.domElement);
  const legend = createCurvatureLegend(document.body, viewer.ramp);

  let patches = [];
  let report = null;
  let stale = false; // the surfaces on screen are newer than `report` (their own is coming)
  let checkingShown = 0; // times the folder said "checking…" (for the tests)
  let asked = { curvature: false, joins: false, crossings: false }; // what the last solve asked the module for
  let overrides = new Map(); // the user's ticks in the joins folder, by join key
  let scale = null; // the curvature map's scale, for the tests

  const curvatureMode = () => CURVATURE_KEY[settings.shading] !== undefined;

  function applyShading() {
    viewer.setZebra({ angleDeg: settings.stripeAngle, widthDeg: settings.stripeWidth });
    scale = null;
    if (!curvatureMode()) {
      legend.hide();
      viewer.setShading(settings.shading);
      return;
    }
    const key = CURVATURE_KEY[settings.shading];
    const withData = patches.filter((p) => p[key]);
    if (withData.length === 0 && patches.length > 0) {
      viewer.setShading('normal');
      if (!hasAnalysis) legend.message(settings.shading, OLD_MODULE);
      else if (!asked.curvature) {
        legend.message(settings.shading, 'computing curvature…');
        requestSolve(); // solved() comes back here with the data
      } else legend.message(settings.shading, 'the solver module returned no curvature for this scene');
      return;
    }
    scale = curvatureScale(withData.map((p) => p[key]), settings);
    viewer.setShading(settings.shading, scale);
    const degenerate = withData.reduce((n, p) => n + (p.degenerateVertices || 0), 0);
    legend.show(settings.shading, scale, degenerate);
  }

  function applyJoins() {
    if (stale) checkingShown++;
    if (!report || report.error) {
      joins.message(stale ? 'checking the joins…'
        : report ? `cannot certify the joins: ${report.error.code}: ${report.error.message}`
          : hasAnalysis ? 'no join report for this scene' : NO_REPORT);
      joins.folder.title(stale ? 'Joins (checking…)' : 'Joins');
      viewer.highlightJoins([]);
      return;
    }
    const keys = highlightedKeys(report, overrides);
    joins.show(report, keys);
    const fails = report.joins.filter((j) => !j.ok).length + (report.seams || []).filter((j) => !j.ok).length;
    joins.folder.title(stale ? 'Joins (checking…)' : fails ? `Joins (${fails} FAIL)` : 'Joins');
    const byKey = new Map(report.joins.map((j) => [joinKey(j), j]));
    viewer.highlightJoins(keys.map((k) => {
      const j = byKey.get(k);
      return { key: k, end: j.end, fail: !j.ok, patch: patches.find((p) => p.name === j.patch) };
    }));
  }

  function onChange(key) {
    if (key === 'wireframe') viewer.setWireframe(settings.wireframe);
    else applyShading();
  }

  function onJoinsOpen() {
    if (hasAnalysis && !asked.crossings) requestSolve(); // solved() comes back with the crossings
  }

  function onToggle(key, on) {
    overrides.set(key, on);
    applyJoins();
  }

  const api = {
    settings,
    /** What to ask the module for in the next solve. */
    solveOptions() {
      return hasAnalysis ? { curvature: curvatureMode(), joins: true, crossings: joins.isOpen() } : {};
    },
    /** After a good solve (the viewer already has the meshes). */
    solved(result, options) {
      patches = result.patches;
      asked = { curvature: Boolean(options.curvature), joins: Boolean(options.joins), crossings: Boolean(options.crossings) };
      // Checked by the solver wrapper (state/join-report.js); or coming after (certified).
      stale = Boolean(result.reportPending);
      if (!stale) report = result.report ?? null;
      applyShading();
      applyJoins();
    },
    /** The join report of the solve on screen, measured after it was drawn. */
    certified(r) {
      report = r;
      stale = false;
      applyJoins();
    },
    /** Another scene opens: the user's join ticks were for the old one. */
    newScene() {
      overrides = new Map();
    },
    /** Settings changed from outside (tests, links): show and apply them. */
    refresh() {
      controls.refresh();
      viewer.setWireframe(settings.wireframe);
      applyShading();
    },
    /** For the tests: the module's H and K of one patch as { mean: [min, max], gauss: [min, max], degenerate, count }. */
    patchCurvature(name) {
      const p = patches.find((q) => q.name === name);
      if (!p || !p.meanCurvature) return null;
      const range = (a) => a.reduce(([lo, hi], x) => [Math.min(lo, x), Math.max(hi, x)], [Infinity, -Infinity]);
      return {
        mean: range(p.meanCurvature), gauss: range(p.gaussCurvature),
        degenerate: p.degenerateVertices, count: p.meanCurvature.length,
      };
    },
    /** For the tests. */
    state() {
      return {
        ...viewer.analysisState(),
        settings: { ...settings },
        scale,
        legend: legend.current(),
        report,
        reportStale: stale,
        checkingShown,
        joinsTitle: joins.folder.domElement.querySelector('.title')?.textContent ?? '',
      };
    },
  };
  // A feature of the document: it hears of new scenes and drawn solves itself.
  doc.on('opened', () => api.newScene());
  doc.on('drawn', (result, job) => api.solved(result, job.options));
  doc.on('certified', (r) => api.certified(r));
  return api;
}
