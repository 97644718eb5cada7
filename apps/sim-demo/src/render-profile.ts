/**
 * How the page draws its 3D view and the robot's camera. A browser without a GPU (a VM, a remote
 * desktop, headless Chromium with `--disable-gpu`) draws WebGL on the CPU, where one frame of the
 * full view (antialiased, with shadows, at the screen's pixel ratio) costs a core about a third
 * of a second: the page then takes every core it can get while a robot moves and starves
 * everything else on the machine. The light profile draws without antialiasing and shadows, at
 * half the pixels, at most five frames a second.
 */

/** What `?render=` may ask for: the profile chosen from the renderer (auto), or one named. */
export const RENDER_SETTINGS = ['auto', 'full', 'light'] as const;
export type RenderSetting = (typeof RENDER_SETTINGS)[number];

export interface RenderProfile {
  name: 'full' | 'light';
  /** Why this profile, for the status line: the setting or the renderer that chose it. */
  reason: string;
  antialias: boolean;
  shadows: boolean;
  /** The 3D view's drawing-buffer pixels per CSS pixel. */
  pixelRatio: number;
  /** The least time from one drawn frame to the next, ms; 0 draws on every animation frame. */
  minFrameIntervalMs: number;
}

/** Renderer names of WebGL drawn by the CPU: Chromium's, Mesa's and Windows' software paths. */
const SOFTWARE_RENDERER = /swiftshader|llvmpipe|lavapipe|softpipe|microsoft basic render|software/i;

/** The light profile's frame interval: five frames a second. */
export const LIGHT_FRAME_INTERVAL_MS = 200;

/** The software rasterizer `rendererName` names (e.g. "SwiftShader"), or undefined for a GPU. */
export function softwareRenderer(rendererName: string | undefined): string | undefined {
  return rendererName === undefined ? undefined : SOFTWARE_RENDERER.exec(rendererName)?.[0];
}

/** The profile for `setting`, given the WebGL renderer's name (undefined: not reported). */
export function chooseRenderProfile(
  setting: RenderSetting,
  rendererName: string | undefined,
  devicePixelRatio: number,
): RenderProfile {
  const software = softwareRenderer(rendererName);
  const lightReason =
    setting === 'light'
      ? '?render=light'
      : setting === 'auto' && software !== undefined
        ? `WebGL drawn in software (${software})`
        : undefined;
  if (lightReason !== undefined) {
    return {
      name: 'light',
      reason: lightReason,
      antialias: false,
      shadows: false,
      pixelRatio: 0.5,
      minFrameIntervalMs: LIGHT_FRAME_INTERVAL_MS,
    };
  }
  return {
    name: 'full',
    reason: setting === 'full' ? '?render=full' : 'WebGL on a GPU',
    antialias: true,
    shadows: true,
    pixelRatio: Math.min(devicePixelRatio, 2),
    minFrameIntervalMs: 0,
  };
}

/**
 * The name of the browser's WebGL renderer (`WEBGL_debug_renderer_info`), read from a throwaway
 * context that is released at once; undefined when the browser does not say.
 */
export function webglRendererName(): string | undefined {
  const canvas = document.createElement('canvas');
  const gl = canvas.getContext('webgl2') ?? canvas.getContext('webgl');
  if (gl === null) return undefined;
  try {
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    const name: unknown = gl.getParameter(
      info === null ? gl.RENDERER : info.UNMASKED_RENDERER_WEBGL,
    );
    return typeof name === 'string' ? name : undefined;
  } finally {
    gl.getExtension('WEBGL_lose_context')?.loseContext();
  }
}
