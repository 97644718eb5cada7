export { describeHalContract } from './contract.js';
export type { HalContractOptions } from './contract.js';
