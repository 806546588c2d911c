// Every number control of the panel, whenever it is built: its slider reachable and
// adjustable from the keyboard (lil-gui's sliders are plain divs), and its box showing
// enough significant digits (lil-gui shows the raw value in a box too narrow for it).
// Works on the live controllers (gui.controllersRecursive()) as folders are rebuilt.

const SIGNIFICANT = 8;
const KEY_STEPS = 100; // arrow keys move by 1/100 of the range (or the slider's own step if coarser)

/** The shortest text of x to SIGNIFICANT digits: 0.000102, 6.2831853, 1e-7, 250. */
export function formatNumber(x) {
  if (!Number.isFinite(x)) return String(x);
  return String(Number(x.toPrecision(SIGNIFICANT)));
}

function enhance(c) {
  c.__access = true;
  const show = c.updateDisplay.bind(c);
  c.updateDisplay = function updateDisplay() {
    show();
    if (!this._inputFocused) this.$input.value = formatNumber(this.getValue());
    if (this._hasSlider) this.$slider.setAttribute('aria-valuenow', formatNumber(this.getValue()));
    return this;
  };
  if (c._hasSlider) {
    const s = c.$slider;
    s.tabIndex = 0;
    s.setAttribute('role', 'slider');
    s.setAttribute('aria-label', c.$name.textContent);
    s.setAttribute('aria-valuemin', formatNumber(c._min));
    s.setAttribute('aria-valuemax', formatNumber(c._max));
    s.addEventListener('keydown', (ev) => {
      const range = c._max - c._min;
      const step = Math.max(c._step || 0, range / KEY_STEPS) * (ev.shiftKey ? 10 : 1);
      const v = c.getValue();
      const next = {
        ArrowRight: v + step, ArrowUp: v + step, ArrowLeft: v - step, ArrowDown: v - step,
        PageUp: v + range / 10, PageDown: v - range / 10,
      }[ev.key];
      if (next !== undefined) {
        ev.preventDefault();
        c.setValue(Math.min(c._max, Math.max(c._min, c._snap(next))));
      } else if (ev.key === 'Home' || ev.key === 'End') {
        ev.preventDefault();
        c.setValue(ev.key === 'Home' ? c._min : c._max); // the ends exactly, not the nearest step
      }
    });
    // A held key is one change (one undo step): it finishes when the key comes up.
    s.addEventListener('keyup', () => c._callOnFinishChange());
    s.addEventListener('blur', () => c._callOnFinishChange());
  }
  c.updateDisplay();
}

/** Keep every number controller of `gui` enhanced, now and after each rebuild. */
export function watchNumberControls(gui) {
  let queued = false;
  const run = () => {
    queued = false;
    for (const c of gui.controllersRecursive()) {
      if (!c.__access && c.$input && typeof c._snap === 'function') enhance(c);
    }
  };
  new MutationObserver(() => {
    if (!queued) {
      queued = true;
      queueMicrotask(run);
    }
  }).observe(gui.domElement, { childList: true, subtree: true });
  run();
}
