// Reading a scene file a user picked or dropped: at most MAX_SCENE_FILE_BYTES (the scene
// text limit of docs/limits.md, which the CLI enforces on the same files), UTF-8 text,
// strict JSON (web/link/strict-json.js: depth, repeated keys), an object with a "patches"
// list. Everything else the solver judges. Each refusal is a SceneFileError whose code is
// the core's name for it (TooLarge, ParseError, InvalidField).
import { parseJsonText, JsonTextError } from '../link/strict-json.js';

export const MAX_SCENE_FILE_BYTES = 16 << 20; // 16 MiB (cpp/common/limits.hpp kSceneBytes)

export class SceneFileError extends Error {
  constructor(code, message) {
    super(message);
    this.name = 'SceneFileError';
    this.code = code;
  }
}

const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

/** A File (or Blob with a name) -> { scene, title }; throws SceneFileError. */
export async function readSceneFile(file) {
  if (file.size > MAX_SCENE_FILE_BYTES) {
    throw new SceneFileError('TooLarge', `the file has ${file.size} bytes; a scene file has at most ${MAX_SCENE_FILE_BYTES} (16 MiB)`);
  }
  let bytes;
  try {
    bytes = await file.arrayBuffer();
  } catch (err) {
    throw new SceneFileError('ParseError', `the file cannot be read (${err.message})`);
  }
  let text;
  try {
    text = new TextDecoder('utf-8', { fatal: true }).decode(bytes);
  } catch {
    throw new SceneFileError('ParseError', 'the file is not UTF-8 text');
  }
  let scene;
  try {
    scene = parseJsonText(text);
  } catch (err) {
    if (err instanceof JsonTextError) throw new SceneFileError(err.code, `the file ${err.kind === 'duplicate' ? 'is not a valid scene: ' : 'is '}${err.message}`);
    throw err;
  }
  if (!isObject(scene)) throw new SceneFileError('InvalidField', `the file holds ${Array.isArray(scene) ? 'a list' : `a ${scene === null ? 'null' : typeof scene}`}, not a scene (a JSON object with "patches")`);
  if (!Array.isArray(scene.patches)) throw new SceneFileError('InvalidField', 'the file holds no scene: a scene has a "patches" list');
  const title = typeof scene.title === 'string' && scene.title.trim() ? scene.title.trim() : null;
  return { scene, title };
}
