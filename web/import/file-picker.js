// The browser's file picker for scene files and CAD files (web/features/files.js): a hidden <input type="file"> (DOM hook
// data-file="input") that open() clicks. The input is emptied after each pick so the same
// file can be picked again.
/** onFile(file) is called with the picked file. Returns { open(), input }. */
export function createFilePicker(onFile) {
  const input = document.createElement('input');
  input.type = 'file';
  input.accept = '.json,application/json,.3dm,.step,.stp,.igs,.iges';
  input.hidden = true;
  input.dataset.file = 'input';
  input.addEventListener('change', () => {
    const file = input.files && input.files[0];
    input.value = '';
    if (file) onFile(file);
  });
  document.body.append(input);
  return { input, open: () => input.click() };
}
