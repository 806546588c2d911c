// The status line: one visible element, written with textContent only.

export function createStatus(el) {
  return {
    info(text) {
      el.classList.remove('error', 'warn');
      el.textContent = text;
    },
    warn(text) {
      el.classList.remove('error');
      el.classList.add('warn');
      el.textContent = text;
    },
    error(text) {
      el.classList.remove('warn');
      el.classList.add('error');
      el.textContent = text;
    },
    text() {
      return el.textContent;
    },
  };
}
