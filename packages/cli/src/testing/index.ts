// @hal/cli/testing: running `hal` in-process in tests: a CliIO that records what a command writes
// (`runHal(argv, captureIO())`) and a keyboard that says it is a TTY, for `hal teleop`.
export { captureIO } from './capture-io.js';
export type { CapturedIO } from './capture-io.js';
export { fakeTty } from './fake-tty.js';
export type { FakeTty } from './fake-tty.js';
