// The reference HAL under its former name, for the tests that still import it from here.
export { ReferenceHAL } from './reference-hal.js';
