// The link in the address bar and the "Share" folder: a scene opened from an example
// keeps its short "#example=<id>" until the user changes something; from then on every
// good solve and every resting camera move rewrites the hash (web/state/hash-sync.js),
// and the link length (with the long-link warning) follows live.
import { createHashSync } from '../state/hash-sync.js';
import { copyLink, shareMessage, longLinkWarning } from '../state/share-link.js';

const messageOf = (err) => (err && err.message ? err.message : String(err));

/** The context's { viewer, panel, status, hooks } -> { opening(), solved(text, grid, summary, edited), copy() } */
export function createShareFeature({ viewer, panel, status, hooks }) {
  let good = null; // the last scene that solved, as solver text, and its grid
  let summary = ''; // that solve's status line
  let long = false; // whether the address bar's link is over LONG_LINK

  function showLength(url) {
    panel.showLinkLength(url.length);
    const warning = longLinkWarning(url.length);
    // Leave an error (a failed solve, a bad link) alone: it says more.
    if (!status.showsError() && (warning || long)) {
      if (warning) status.warn(`${summary}; ${warning}`);
      else status.info(summary);
    }
    long = Boolean(warning);
  }

  const sync = createHashSync({
    // The last good scene: a camera move after a failed solve must not link the broken one.
    snapshot: () => good && { scene: JSON.parse(good.text), grid: { ...good.grid }, camera: viewer.getCamera() },
    onWritten: showLength,
    onError: (err) => {
      if (err?.code !== 'TooLarge') return status.error(`cannot make a link: ${messageOf(err)}`);
      // A scene past a link's 1 MiB (an imported CAD part): it works, it is kept as a file.
      panel.showLinkLength(null);
      if (!status.showsError()) status.warn(`${summary}; ${messageOf(err)}: keep it with File → export scene JSON`);
    },
  });
  sync.watchCamera(viewer.controls);

  return {
    /** A scene is about to open from a hash or the gallery: its own hash stands. */
    opening() {
      good = null;
      sync.cancel();
    },

    /** After a good solve; `edited` is false for the solve that opens a scene. */
    solved(text, grid, line, edited) {
      good = { text, grid: { ...grid } };
      summary = line;
      if (edited) sync.request();
      else showLength(location.href);
    },

    async copy() {
      try {
        await sync.flush();
        const shared = await copyLink(location.href);
        hooks.lastLink = shared.url;
        panel.showLinkLength(shared.chars);
        if (shared.long) status.warn(shareMessage(shared));
        else status.info(shareMessage(shared));
      } catch (err) {
        status.error(`cannot copy the link: ${messageOf(err)}`);
      }
    },
  };
}
