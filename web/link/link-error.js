// The one error type of the link codec: its message is meant for the status line,
// so it says what was wrong with the link in words a user can act on.

export class LinkError extends Error {
  constructor(message, options) {
    super(message, options);
    this.name = 'LinkError';
  }
}
