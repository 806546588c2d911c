// A discrete normal field's λ weights by region: nine sliders (3×3 regions of the
// sample grid, u down the rows, v across), each 0..10, written to the scene as the
// per-sample list normals.lambda_weights (web/state/region-weights.js).
// DOM hooks: data-region-weights="<patch>" on the folder, data-region-weight="<r>.<c>"
// on each slider (r: u region, c: v region, 0..2).
import { escapeHtml } from './html-text.js';
import {
  SPLIT, WEIGHT_MIN, WEIGHT_MAX, discreteGrid, regionSpan, regionValuesFrom,
} from '../state/region-weights.js';

const STEP = 0.1;
const short = (x) => String(Number(x.toFixed(2))).replace(/^0\./, '.');

/**
 * Add the folder to `parent` for a scene patch with a discrete normal field (otherwise
 * nothing, and null). onChange(regions) gets the nine values, row-major.
 */
export function buildRegionWeightControls(parent, patch, onChange) {
  const grid = discreteGrid(patch);
  if (!grid) return null;
  const [np, mp] = grid;
  const folder = parent.addFolder(escapeHtml('λ weights by region (u rows, v columns)'));
  folder.domElement.classList.add('region-weights');
  folder.domElement.dataset.regionWeights = patch.name;
  // Scene weights given as an expression cannot be shown as nine numbers; say so.
  if (typeof patch.normals.lambda_weights === 'string') {
    folder.domElement.title = 'the scene gives these weights as an expression; moving a slider replaces it';
  }

  const values = regionValuesFrom(patch.normals.lambda_weights, np, mp);
  const model = {};
  const keys = [];
  for (let r = 0; r < SPLIT; r++) {
    const [u0, u1] = regionSpan(r, np);
    for (let c = 0; c < SPLIT; c++) {
      const [v0, v1] = regionSpan(c, mp);
      const key = `w${r}${c}`;
      keys.push(key);
      model[key] = values[r * SPLIT + c];
      if (u0 < 0 || v0 < 0) continue; // a grid of fewer than 3 samples leaves a region empty
      const ctrl = folder
        .add(model, key, WEIGHT_MIN, WEIGHT_MAX, STEP)
        .name(escapeHtml(`u ${short(u0)}–${short(u1)}, v ${short(v0)}–${short(v1)}`))
        .onChange(() => onChange(keys.map((k) => model[k])));
      ctrl.domElement.dataset.regionWeight = `${r}.${c}`;
      ctrl.domElement.title = `λ weight of the normal samples with u in [${u0.toFixed(3)}, ${u1.toFixed(3)}] and v in [${v0.toFixed(3)}, ${v1.toFixed(3)}]`;
    }
  }
  folder.close();
  return folder;
}
