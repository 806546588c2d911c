// The panel's "Model" folder: every patch with its kind and name (renamed in place),
// visibility, selection, duplicate and delete; deleting a surface a blend or a fill names
// asks what to do with them; parameters no expression uses can be removed. Names are set
// as text (a name with markup shows its characters). It reports what the user asked;
// web/features/build.js makes the edits through the document's door.

import { conditionSources } from '../state/patch-references.js';
import { kindInfo } from '../state/patch-kinds.js';

/** The patches `patch`'s conditions come from: surfaces its ends or borders name, patches its chained ends continue, a fill's loop. */
export const upstreamOf = conditionSources;

function button(label, title, onClick, action) {
  const b = document.createElement('button');
  b.type = 'button';
  b.textContent = label;
  b.title = title;
  b.setAttribute('aria-label', title);
  b.dataset.action = action;
  b.addEventListener('click', onClick);
  return b;
}

/**
 * handlers: { onSelect(name), onRename(old, next), onVisible(name, on), onDuplicate(name),
 *   onDelete(name, dependents: 'delete' | 'detach' | undefined), onRemoveParameter(name) }.
 */
export function buildOutliner(gui, handlers) {
  const folder = gui.addFolder('Model');
  folder.domElement.classList.add('outliner');
  const list = document.createElement('ul');
  list.className = 'outliner-list';
  const unused = document.createElement('div');
  unused.className = 'outliner-unused';
  // The model's bodies from the last solve's report: closed or open, area, volume (issue 36).
  const bodies = document.createElement('ul');
  bodies.className = 'outliner-bodies';
  folder.$children.append(list, bodies, unused);
  let selected = null;
  let hidden = new Set();

  function row(patch, dependents) {
    const li = document.createElement('li');
    li.dataset.patch = patch.name;
    li.classList.toggle('selected', patch.name === selected);
    const kind = document.createElement('span');
    kind.className = 'outliner-kind';
    kind.textContent = kindInfo(patch.kind).label;
    const name = document.createElement('input');
    name.type = 'text';
    name.value = patch.name;
    name.setAttribute('aria-label', `name of ${patch.name}`);
    name.addEventListener('change', () => {
      if (name.value !== patch.name) handlers.onRename(patch.name, name.value);
    });
    name.addEventListener('focus', () => handlers.onSelect(patch.name));
    const eye = document.createElement('input');
    eye.type = 'checkbox';
    eye.checked = !hidden.has(patch.name);
    eye.title = 'visible';
    eye.setAttribute('aria-label', `show ${patch.name}`);
    eye.addEventListener('change', () => handlers.onVisible(patch.name, eye.checked));
    const tools = document.createElement('span');
    tools.className = 'outliner-tools';
    // What meets another patch's edge cannot be copied: its copy would meet that edge too
    // (three sheets; web/state/scene-build.js duplicatePatch says the same).
    const from = upstreamOf(patch);
    const copy = button('❏', `duplicate ${patch.name}`, () => handlers.onDuplicate(patch.name), 'duplicate');
    if (from.length) {
      copy.disabled = true;
      copy.title = `${patch.name} meets ${from.join(', ')}: a copy would meet the same edges (detach it first to duplicate it)`;
    }
    tools.append(
      button('◎', `select ${patch.name}`, () => handlers.onSelect(patch.name), 'select'),
      copy,
      button('✕', `delete ${patch.name}`, () => (dependents.length ? ask(li, patch.name, dependents) : handlers.onDelete(patch.name)), 'delete'),
    );
    li.append(eye, kind, name, tools);
    // The chain: what this patch's conditions come from (they are re-derived when those change).
    if (from.length) {
      const deps = document.createElement('span');
      deps.className = 'outliner-deps';
      deps.textContent = `← ${from.join(', ')}`;
      deps.title = `derived from ${from.join(', ')}`;
      li.append(deps);
    }
    return li;
  }

  // A surface that blends or fills name: delete them too, or detach them to typed data.
  function ask(li, name, dependents) {
    li.querySelector('.outliner-ask')?.remove();
    const box = document.createElement('div');
    box.className = 'outliner-ask';
    box.setAttribute('role', 'alertdialog');
    const text = document.createElement('span');
    text.textContent = `${dependents.join(', ')} ${dependents.length === 1 ? 'names' : 'name'} ${name}:`;
    box.append(
      text,
      button('delete them too', `delete ${name} and ${dependents.join(', ')}`, () => handlers.onDelete(name, 'delete'), 'delete-dependents'),
      button('detach them', `delete ${name}; ${dependents.join(', ')} keep typed conditions`, () => handlers.onDelete(name, 'detach'), 'detach-dependents'),
      button('cancel', 'keep it', () => box.remove(), 'cancel'),
    );
    li.append(box);
  }

  return {
    folder,
    /** patches: the scene's; dependentsOf(name) -> names of blends and fills that name it. */
    show(patches, dependentsOf, unusedParameters) {
      list.replaceChildren(...patches.map((p) => row(p, dependentsOf(p.name))));
      if (!patches.length) {
        const empty = document.createElement('li');
        empty.className = 'outliner-empty';
        empty.textContent = 'No patch yet: add a surface in Build.';
        list.append(empty);
      }
      unused.replaceChildren();
      if (unusedParameters.length) {
        const label = document.createElement('span');
        label.textContent = 'unused parameters: ';
        unused.append(label, ...unusedParameters.map((n) => button(`✕ ${n}`, `remove the unused parameter ${n}`, () => handlers.onRemoveParameter(n), 'remove-parameter')));
      }
    },
    /** lines: one text per body (state/join-report.js bodyText), or [] before a report. */
    showBodies(lines) {
      bodies.replaceChildren(...lines.map((text) => {
        const li = document.createElement('li');
        li.className = 'outliner-body';
        li.textContent = text;
        return li;
      }));
    },
    select(name) {
      selected = name;
      for (const li of list.children) li.classList.toggle('selected', li.dataset.patch === name);
    },
    setHidden(names) {
      hidden = new Set(names);
    },
  };
}
