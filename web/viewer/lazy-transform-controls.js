// three's TransformControls, built on first use: its constructor builds every handle's
// geometry and material, about 80 ms of a cold start under a software GL (twice: the
// placement gizmo and the control-point editor), which the first frame does not need.
import { TransformControls } from 'three/addons/controls/TransformControls.js';

/**
 * get(): the controls, built at the first call (disabled, their helper in `scene`, a change
 * renders, a drag pauses `orbit`; then setUp(controls) once). peek(): them, or null before.
 */
export function lazyTransformControls({ scene, camera, dom, orbit, render, setUp = () => {} }) {
  let controls = null;
  return {
    get() {
      if (!controls) {
        controls = new TransformControls(camera, dom);
        controls.enabled = false;
        scene.add(controls.getHelper());
        controls.addEventListener('change', render);
        controls.addEventListener('dragging-changed', (e) => {
          orbit.enabled = !e.value;
        });
        setUp(controls);
      }
      return controls;
    },
    peek: () => controls,
  };
}
