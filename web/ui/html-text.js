// lil-gui writes controller names, folder titles and option labels as HTML markup.
// Every string we hand it passes through here, so text from a scene or a link is
// shown literally and never parsed as markup.

const ENTITIES = { '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' };

export function escapeHtml(text) {
  return String(text).replace(/[&<>"']/g, (ch) => ENTITIES[ch]);
}
