// Runs `hal` in-process from a test outside the package, with @hal/cli/testing's captureIO.
export { captureIO } from '@hal/cli/testing';
export type { CapturedIO } from '@hal/cli/testing';
