// The control panel (three's bundled lil-gui): example picker, grid resolution, and
// the per-scene folders that are rebuilt whenever another example opens.
import GUI from 'three/addons/libs/lil-gui.module.min.js';
import { escapeHtml } from './html-text.js';
import { buildParameterFolder } from './parameter-controls.js';
import { buildOperatorFolders } from './operator-controls.js';

const GRID_MIN = 4;
const GRID_MAX = 256;

/**
 * examples: [{id, title}]; grid: {nu, nv} (edited in place);
 * onExample(id), onGridChange(), onParameterChange();
 * operatorHandlers: see buildOperatorFolders (methodOf, onParam, onOrder, onMethod).
 */
export function createPanel({ examples, grid, onExample, onGridChange, onParameterChange, operatorHandlers }) {
  const gui = new GUI({ title: 'pdesurf', width: 320 });
  gui.domElement.id = 'panel';

  // lil-gui parses option labels as HTML: escape them, and keep labels unique.
  const options = {};
  for (const e of examples) {
    let label = escapeHtml(e.title);
    while (label in options) label += ' ';
    options[label] = e.id;
  }
  const picker = { example: examples[0].id };
  const pickerCtrl = gui.add(picker, 'example', options).name('example').onChange((id) => onExample(id));
  pickerCtrl.domElement.dataset.control = 'example';

  const gridFolder = gui.addFolder('Grid');
  for (const key of ['nu', 'nv']) {
    const c = gridFolder.add(grid, key, GRID_MIN, GRID_MAX, 1).onChange(onGridChange);
    c.domElement.dataset.grid = key;
  }
  gridFolder.close();

  let paramFolder = null;
  let operators = null;
  // Scene folders are appended as they are built; keep the grid folder last.
  const gridToEnd = () => gui.$children.appendChild(gridFolder.domElement);

  return {
    gui,

    /** Reflect an example opened from elsewhere (hash, first load) without firing onChange. */
    setExample(id) {
      picker.example = id;
      pickerCtrl.updateDisplay();
    },

    /** New scene: fresh parameter sliders; operator folders wait for its first solve. */
    showScene(scene) {
      if (paramFolder) paramFolder.destroy();
      if (operators) operators.destroy();
      operators = null;
      paramFolder = buildParameterFolder(gui, scene, onParameterChange);
      gridToEnd();
    },

    /** After a successful solve: build operator folders once per scene, else refresh them. */
    showSolved(patches) {
      if (operators) operators.update(patches);
      else {
        operators = buildOperatorFolders(gui, patches, operatorHandlers);
        gridToEnd();
      }
    },
  };
}
