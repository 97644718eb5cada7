// Runs `hal` in-process from a test outside the package: the package's own capture fixture.
export { captureIO } from '../../packages/cli/src/capture-io.fixture.js';
export type { CapturedIO } from '../../packages/cli/src/capture-io.fixture.js';
