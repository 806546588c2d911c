// The "Joins" folder of the panel: one entry per join of the scene from the module's
// report (patch, end, surface, promised level, G0 gap, G1 angle, G2 mismatch, fold,
// verdict), the crossings found, and a checkbox per join that highlights it on the
// surface (failing joins start ticked). Built with createElement/textContent only:
// patch and surface names from a scene or a link are shown literally.
// DOM hooks: [data-folder="joins"], .joins-summary, [data-join="<patch>:<side>:<met>:<edge>"] with
// data-verdict="ok" | "fail", its checkbox input, .joins-seam[data-seam] and .joins-centre[data-centre] with
// data-verdict, .joins-crossing, .joins-message.
import { joinFigures, crossingText, joinKey, centreText, seamText } from '../state/join-report.js';

function el(tag, className, text) {
  const node = document.createElement(tag);
  if (className) node.className = className;
  if (text !== undefined) node.textContent = text;
  return node;
}

/**
 * onToggle(key, on) when a checkbox changes; onOpen() when the user opens the folder.
 * Returns { folder, isOpen(), show(report, highlighted), message(text) }.
 */
export function buildJoinsFolder(gui, onToggle, onOpen) {
  const folder = gui.addFolder('Joins');
  folder.domElement.dataset.folder = 'joins';
  const isOpen = () => folder.$title.getAttribute('aria-expanded') === 'true';
  // lil-gui toggles on a title click (Enter and Space click too); its own listener runs first.
  folder.$title.addEventListener('click', () => {
    if (isOpen()) onOpen();
  });
  const body = el('div', 'joins');
  folder.$children.append(body);

  function clear() {
    body.replaceChildren();
  }

  function entry(j, on) {
    const li = el('li', `joins-item ${j.ok ? 'ok' : 'fail'}`);
    li.dataset.join = `${j.patch}:${j.end}:${j.surface}:${j.edge}`;
    li.dataset.verdict = j.ok ? 'ok' : 'fail';
    const label = el('label', 'joins-head');
    const box = el('input');
    box.type = 'checkbox';
    box.checked = on;
    box.title = 'highlight this join on the surface';
    box.addEventListener('change', () => onToggle(joinKey(j), box.checked));
    const what = el('span', 'joins-what');
    what.append(
      el('span', 'joins-name', `“${j.patch}”`),
      document.createTextNode(` ${j.end} → `),
      el('span', 'joins-name', `“${j.surface}”`),
      document.createTextNode(j.edge ? ` (${j.edge})` : ''),
    );
    const level = el('span', 'joins-level', j.level);
    level.title = 'continuity the scene promises here';
    const verdict = el('span', `joins-verdict ${j.ok ? 'ok' : 'fail'}`, j.ok ? 'ok' : 'FAIL');
    label.append(box, what, level, verdict);
    const figures = el('div', 'joins-figures');
    for (const [name, value] of joinFigures(j)) {
      const f = el('span', 'joins-figure');
      f.append(el('span', 'joins-figure-name', `${name} `), el('span', 'joins-figure-value', value));
      if (name === 'fold' && j.fold) f.classList.add('bad');
      figures.append(f);
    }
    if (j.degenerate > 0) figures.append(el('span', 'joins-figure', `${j.degenerate} degenerate points`));
    li.append(label, figures);
    return li;
  }

  return {
    folder,
    isOpen,
    /** report: normaliseReport()'s result; highlighted: keys that are ticked. */
    show(report, highlighted) {
      clear();
      const ticked = new Set(highlighted);
      const fails = report.joins.filter((j) => !j.ok).length;
      const n = report.joins.length;
      const crossings = report.crossingsChecked
        ? `${report.crossings.length} ${report.crossings.length === 1 ? 'crossing' : 'crossings'}`
        : 'crossings not checked yet';
      const summary = `${n} ${n === 1 ? 'join' : 'joins'}, ${fails} failing; ${crossings}`;
      body.append(el('div', `joins-summary ${report.ok ? 'ok' : 'fail'}`, summary));
      if (n === 0) body.append(el('div', 'joins-message', 'no joins in this scene'));
      const list = el('ul', 'joins-list');
      for (const j of report.joins) list.append(entry(j, ticked.has(joinKey(j))));
      body.append(list);
      // One line per seam and per fill's centre, with its verdict.
      const verdicts = (className, items, textOf, key) => {
        if (!items?.length) return;
        const ul = el('ul', `${className}s`);
        for (const item of items) {
          const li = el('li', `${className} ${item.ok ? 'ok' : 'fail'}`, textOf(item));
          li.dataset[key] = item.patch;
          li.dataset.verdict = item.ok ? 'ok' : 'fail';
          ul.append(li);
        }
        body.append(ul);
      };
      verdicts('joins-seam', report.seams, seamText, 'seam');
      verdicts('joins-centre', report.centres, centreText, 'centre');
      if (report.crossings.length) {
        const cl = el('ul', 'joins-crossings');
        for (const c of report.crossings) cl.append(el('li', 'joins-crossing', crossingText(c)));
        body.append(cl);
      } else if (report.crossingsChecked) body.append(el('div', 'joins-message', 'no crossings found'));
      else body.append(el('div', 'joins-message', 'checking crossings…'));
    },
    /** No report to show (an older module, or the last solve failed): say why. */
    message(text) {
      clear();
      body.append(el('div', 'joins-message', text));
    },
  };
}
