export { describeHalContract } from './contract.js';
export type { HalContractOptions } from './contract.js';
export { fencedBlocks, runDocExample } from './doc-example.js';
export type { ExampleModules } from './doc-example.js';
export { ReferenceHAL } from './reference-hal.js';
export { CALL_SAMPLES } from './contract-samples.js';
