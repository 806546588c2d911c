// Shows a message when main.js or any module it imports cannot be fetched (e.g. node_modules
// not installed). A classic script after the module tag: it runs while the page is still
// being parsed, so before the module script can run or fail.
document.getElementById('main-script').addEventListener('error', () => {
  const status = document.getElementById('status');
  status.className = 'error';
  status.textContent = 'cannot load the page scripts (run npm ci)';
});
