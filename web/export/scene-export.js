// The scene as a file: the page state (the scene object the solver sees) as JSON, which
// the page's "open scene file…" and the CLI (pdesurf sample|export|check FILE) read back.
// Pretty-printed unless that would pass the scene-file limit the CLI and the page enforce.
import { MAX_SCENE_FILE_BYTES } from '../import/scene-file.js';

/** scene object -> file text (ends with a newline). */
export function sceneFileText(scene) {
  const pretty = `${JSON.stringify(scene, null, 2)}\n`;
  if (new TextEncoder().encode(pretty).length <= MAX_SCENE_FILE_BYTES) return pretty;
  return `${JSON.stringify(scene)}\n`;
}
