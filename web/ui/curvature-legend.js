// The legend of a curvature map, over the bottom of the view: the quantity, the colour
// ramp (the same three.js Lut the surface uses), the numbers at its ends (and 0 where it
// falls inside), the data's own range and how much was clamped; or a message when the
// module gave no curvature. Built with createElement/textContent only.
// DOM hooks: #curvature-legend, data-legend="title" | "min" | "zero" | "max" | "data" | "message".
import { paintRamp } from '../viewer/curvature-colors.js';
import { formatValue } from '../state/curvature-scale.js';

function el(tag, className, text) {
  const node = document.createElement(tag);
  if (className) node.className = className;
  if (text !== undefined) node.textContent = text;
  return node;
}

const TITLES = { mean: 'mean curvature H', gauss: 'Gaussian curvature K' };

/** parent: where the legend goes (the body); lut: the viewer's ramp. */
export function createCurvatureLegend(parent, lut) {
  const root = el('div');
  root.id = 'curvature-legend';
  root.hidden = true;
  root.setAttribute('role', 'group');
  root.setAttribute('aria-label', 'colour legend');
  const title = el('div', 'legend-title');
  title.dataset.legend = 'title';
  const ramp = el('canvas', 'legend-ramp');
  ramp.width = 256;
  ramp.height = 1;
  const ticks = el('div', 'legend-ticks');
  const lo = el('span', 'legend-min');
  const zero = el('span', 'legend-zero', '0');
  const hi = el('span', 'legend-max');
  lo.dataset.legend = 'min';
  zero.dataset.legend = 'zero';
  hi.dataset.legend = 'max';
  ticks.append(lo, zero, hi);
  const data = el('div', 'legend-data');
  data.dataset.legend = 'data';
  const message = el('div', 'legend-message');
  message.dataset.legend = 'message';
  root.append(title, ramp, ticks, data, message);
  parent.append(root);

  const showParts = (on) => {
    for (const n of [ramp, ticks, data]) n.hidden = !on;
    message.hidden = on;
  };

  return {
    element: root,
    /** null when hidden, else { title, message (null while the ramp shows), min, max, data }. */
    current() {
      if (root.hidden) return null;
      if (!message.hidden) return { title: title.textContent, message: message.textContent };
      return { title: title.textContent, message: null, min: lo.textContent, max: hi.textContent, data: data.textContent };
    },
    hide() {
      root.hidden = true;
    },
    /** mode: 'mean' | 'gauss'; scale: curvatureScale()'s result; degenerate: vertex count. */
    show(mode, scale, degenerate = 0) {
      root.hidden = false;
      showParts(true);
      title.textContent = TITLES[mode] || mode;
      lut.setMin(scale.min);
      lut.setMax(scale.max);
      paintRamp(lut, ramp);
      lo.textContent = formatValue(scale.min);
      hi.textContent = formatValue(scale.max);
      const inside = scale.min < 0 && scale.max > 0;
      zero.hidden = !inside;
      if (inside) zero.style.left = `${(100 * -scale.min) / (scale.max - scale.min)}%`;
      const parts = [`data ${formatValue(scale.dataMin)} … ${formatValue(scale.dataMax)}`];
      if (scale.clamped > 0) parts.push(`${(100 * scale.clamped).toFixed(1)} % clamped`);
      if (degenerate > 0) parts.push(`${degenerate} degenerate vertices (shown as 0)`);
      data.textContent = parts.join('; ');
    },
    /** A mode that cannot be shown: the reason instead of the ramp. */
    message(mode, text) {
      root.hidden = false;
      showParts(false);
      title.textContent = TITLES[mode] || mode;
      message.textContent = text;
    },
  };
}
