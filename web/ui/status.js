// The status line: one visible element, written with textContent only.

export function createStatus(el) {
  let before = null; // { text, className } under a "solving…" line
  return {
    /** ms: how long the running solve has taken, or null when it ended (the line comes back). */
    busy(ms) {
      if (ms === null) {
        if (before && el.classList.contains('busy')) {
          el.textContent = before.text;
          el.className = before.className;
        }
        el.classList.remove('busy');
        before = null;
        return;
      }
      if (!before) before = { text: el.textContent, className: el.className };
      el.classList.remove('error', 'warn');
      el.classList.add('busy');
      el.textContent = `solving… ${(ms / 1000).toFixed(1)} s`;
    },
    info(text) {
      el.classList.remove('busy');
      before = null;
      el.classList.remove('error', 'warn');
      el.textContent = text;
    },
    warn(text) {
      el.classList.remove('busy');
      before = null;
      el.classList.remove('error');
      el.classList.add('warn');
      el.textContent = text;
    },
    error(text) {
      el.classList.remove('busy');
      before = null;
      el.classList.remove('warn');
      el.classList.add('error');
      el.textContent = text;
    },
    text() {
      return el.textContent;
    },
    /** Whether the line says what went wrong (an error is left alone by passing notes). */
    showsError() {
      return el.classList.contains('error');
    },
  };
}
