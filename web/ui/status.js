// The status line: one visible element, written with textContent only.

export function createStatus(el) {
  return {
    info(text) {
      el.classList.remove('error');
      el.textContent = text;
    },
    error(text) {
      el.classList.add('error');
      el.textContent = text;
    },
    text() {
      return el.textContent;
    },
  };
}
