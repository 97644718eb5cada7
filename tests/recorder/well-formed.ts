// What every reader of a recording expects (each message valid against its channel's JSON Schema,
// log times that never go backwards): the recorder's own check, for the cross-process tests.
export { expectWellFormed } from '@hal/recorder/testing';
