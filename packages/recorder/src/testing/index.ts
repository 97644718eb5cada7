// @hal/recorder/testing: a vitest check that a recording read back is what every reader expects
// (each message valid against its channel's JSON Schema, log times never going backwards). It
// needs vitest and ajv, optional peers of this package.
export { expectWellFormed } from './well-formed.js';
