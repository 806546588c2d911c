// Hands a file to the browser's download machinery: a Blob behind a temporary object URL,
// clicked through an <a download> that never enters the document. The URL is revoked a
// little later (revoking at once can cancel the download in some browsers).
const REVOKE_AFTER_MS = 30_000;

/** Start the download of `data` (Blob, ArrayBuffer, typed array or string) as `fileName`. */
export function downloadFile(data, fileName, type) {
  const blob = data instanceof Blob ? data : new Blob([data], { type });
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = fileName;
  a.rel = 'noopener';
  a.click();
  setTimeout(() => URL.revokeObjectURL(url), REVOKE_AFTER_MS);
  return blob.size;
}
