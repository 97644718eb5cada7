import * as THREE from 'three';
import type { CameraOptions } from '../camera.js';
import type { FrameSource } from '../hal/options.js';
import type { WorldScene } from './scene.js';

export interface ThreeFrameSourceOptions extends CameraOptions {
  /** JPEG quality, 0..1. Default 0.85. */
  quality?: number;
  /** Draw into this canvas (e.g. one shown on the page); default an offscreen one. */
  canvas?: HTMLCanvasElement;
  /** Smooth edges (MSAA). Default true; off halves the cost of a frame drawn in software. */
  antialias?: boolean;
  /** Cast shadows from the scene's sun. Default true. */
  shadows?: boolean;
}

/** A {@link FrameSource} for browsers: renders the robot's view with WebGL into a small canvas. */
export interface ThreeFrameSource {
  /** Pass to `new SimulationHAL({ frameSource })`. */
  frameSource: FrameSource;
  /** Renders the robot's current view into the canvas (call per animation frame to show it live). */
  render(robotId: string): void;
  readonly canvas: HTMLCanvasElement;
  readonly renderer: THREE.WebGLRenderer;
  dispose(): void;
}

/** Renders what a robot sees from a {@link WorldScene}, 320x240 by default, as JPEG frames. */
export function createThreeFrameSource(
  view: WorldScene,
  options: ThreeFrameSourceOptions = {},
): ThreeFrameSource {
  const width = options.width ?? 320;
  const height = options.height ?? 240;
  const canvas = options.canvas ?? document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  const renderer = new THREE.WebGLRenderer({
    canvas,
    antialias: options.antialias ?? true,
    preserveDrawingBuffer: true,
  });
  renderer.setPixelRatio(1);
  renderer.shadowMap.enabled = options.shadows ?? true;
  renderer.setSize(width, height, false);
  const camera = new THREE.PerspectiveCamera();
  // only the camera's own options: the model is strict, and refuses the renderer's
  const { quality: _q, canvas: _c, antialias: _a, shadows: _s, ...cameraOptions } = options;
  const render = (robotId: string) => {
    const robot = view.world.robot(robotId);
    view.robotCamera(robot, { ...cameraOptions, width, height }, camera);
    const overlays = view.overlaysVisible;
    view.overlaysVisible = false;
    renderer.render(view.scene, camera);
    view.overlaysVisible = overlays;
  };
  return {
    canvas,
    renderer,
    render,
    frameSource: async (_world, robot) => {
      render(robot.id);
      return canvas.toDataURL('image/jpeg', options.quality ?? 0.85);
    },
    dispose: () => renderer.dispose(),
  };
}
