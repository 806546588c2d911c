// The "Share" folder: a "copy link" button and a read-only line with the length of
// the link in the address bar (kept current), flagged past LONG_LINK characters (chat
// and mail tools, and some servers, cut longer URLs). DOM hooks: data-share="copy" / "length".
import { escapeHtml } from './html-text.js';
import { LONG_LINK } from '../state/share-link.js';

/** onCopy() does the work; returns { folder (its element), showLength(chars) }. */
export function buildShareFolder(gui, onCopy) {
  const folder = gui.addFolder('Share');
  folder.domElement.dataset.folder = 'share';
  const actions = { copy: () => onCopy() };
  folder.add(actions, 'copy').name(escapeHtml('copy link')).domElement.dataset.share = 'copy';
  // A disabled text field: lil-gui sets an input's value, which is never parsed as markup.
  const model = { length: '—' };
  const lengthCtrl = folder.add(model, 'length').name(escapeHtml('link length')).disable();
  lengthCtrl.domElement.dataset.share = 'length';
  return {
    folder: folder.domElement,
    /** chars: the link's length, or null when the scene is too large for one. */
    showLength(chars) {
      const long = chars === null || chars > LONG_LINK;
      model.length = chars === null ? 'too large for a link' : long ? `${chars} characters (> ${LONG_LINK})` : `${chars} characters`;
      lengthCtrl.updateDisplay();
      lengthCtrl.domElement.classList.toggle('warn', long);
    },
  };
}
