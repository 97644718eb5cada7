/**
 * Runs `run` in a later turn of the event loop, after the input already waiting has been read:
 * setImmediate in Node, a zero timeout in a browser.
 */
export const nextTurn: (run: () => void) => void =
  typeof setImmediate === 'function' ? (run) => setImmediate(run) : (run) => setTimeout(run, 0);
