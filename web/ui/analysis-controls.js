// The "Analysis" folder of the panel: the shading mode (normal, zebra stripes, mean or
// Gaussian curvature map), the wireframe overlay, and the settings of the active mode
// only (stripe direction and width for zebra; the colour scale for the curvature maps).
// DOM hooks: data-analysis="shading" | "wireframe" | "stripeAngle" | "stripeWidth" |
// "scale" | "percentile" | "min" | "max".
import { escapeHtml } from './html-text.js';

export const SHADINGS = {
  normal: 'normal',
  'zebra stripes': 'zebra',
  'mean curvature H': 'mean',
  'Gaussian curvature K': 'gauss',
};
const SCALES = {
  'symmetric about 0': 'symmetric',
  'percentile range': 'percentile',
  'fixed range': 'fixed',
};

const escapedKeys = (o) => Object.fromEntries(Object.entries(o).map(([k, v]) => [escapeHtml(k), v]));

export function defaultAnalysisSettings() {
  return { shading: 'normal', wireframe: false, stripeAngle: 90, stripeWidth: 6, scale: 'symmetric', percentile: 98, min: -1, max: 1 };
}

/**
 * settings: defaultAnalysisSettings() (edited in place); onChange(key) after any edit.
 * Returns { folder, refresh() } (refresh after settings changed elsewhere).
 */
export function buildAnalysisFolder(gui, settings, onChange) {
  const folder = gui.addFolder('Analysis');
  folder.domElement.dataset.folder = 'analysis';
  const ctrls = {};
  const add = (key, ...args) => {
    const c = folder.add(settings, key, ...args).onChange(() => {
      showRelevant();
      onChange(key);
    });
    c.domElement.dataset.analysis = key;
    ctrls[key] = c;
    return c;
  };
  add('shading', escapedKeys(SHADINGS)).name('shading');
  add('wireframe').name('wireframe overlay');
  add('stripeAngle', 0, 180, 1).name(escapeHtml('stripe direction °'));
  add('stripeWidth', 1, 30, 0.5).name(escapeHtml('stripe width °'));
  add('scale', escapedKeys(SCALES)).name('colour scale');
  add('percentile', 50, 100, 0.5).name(escapeHtml('percentile %'));
  add('min').name('min');
  add('max').name('max');

  function showRelevant() {
    const s = settings.shading;
    const curv = s === 'mean' || s === 'gauss';
    ctrls.stripeAngle.show(s === 'zebra');
    ctrls.stripeWidth.show(s === 'zebra');
    ctrls.scale.show(curv);
    ctrls.percentile.show(curv && settings.scale !== 'fixed');
    ctrls.min.show(curv && settings.scale === 'fixed');
    ctrls.max.show(curv && settings.scale === 'fixed');
  }
  showRelevant();

  return {
    folder,
    refresh() {
      for (const c of Object.values(ctrls)) c.updateDisplay();
      showRelevant();
    },
  };
}
