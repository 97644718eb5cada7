export { fromThree, toThree } from './coordinates.js';
export { WorldScene } from './scene.js';
export type { WorldSceneOptions } from './scene.js';
export type { OccupancyGridView } from './planning-overlays.js';
export { createThreeFrameSource } from './frame.js';
export type { ThreeFrameSource, ThreeFrameSourceOptions } from './frame.js';
