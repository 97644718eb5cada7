export { fromThree, toThree, WorldScene } from './scene.js';
export type { OccupancyGridView, WorldSceneOptions } from './scene.js';
export { createThreeFrameSource } from './frame.js';
export type { ThreeFrameSource, ThreeFrameSourceOptions } from './frame.js';
