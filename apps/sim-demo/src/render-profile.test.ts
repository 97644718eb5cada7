import { describe, expect, it } from 'vitest';
import {
  chooseRenderProfile,
  LIGHT_FRAME_INTERVAL_MS,
  softwareRenderer,
} from './render-profile.js';
import { readUrlSettings } from './url-settings.js';

// Renderer names as browsers report them through WEBGL_debug_renderer_info.
const SWIFTSHADER =
  'ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)';
const LLVMPIPE = 'llvmpipe (LLVM 15.0.6, 256 bits)';
const GPU = 'ANGLE (NVIDIA, NVIDIA GeForce RTX 3060 (0x00002504) Direct3D11 vs_5_0 ps_5_0, D3D11)';

describe('the render profile', () => {
  it('names the software rasterizer of a renderer drawn by the CPU, and none for a GPU', () => {
    expect(softwareRenderer(SWIFTSHADER)).toBe('SwiftShader');
    expect(softwareRenderer(LLVMPIPE)).toBe('llvmpipe');
    expect(softwareRenderer('Microsoft Basic Render Driver')).toBe('Microsoft Basic Render');
    expect(softwareRenderer(GPU)).toBeUndefined();
    expect(softwareRenderer(undefined)).toBeUndefined();
  });

  it('draws light on its own on a software renderer, and says why', () => {
    const profile = chooseRenderProfile('auto', SWIFTSHADER, 1);
    expect(profile).toEqual({
      name: 'light',
      reason: 'WebGL drawn in software (SwiftShader)',
      antialias: false,
      shadows: false,
      pixelRatio: 0.5,
      minFrameIntervalMs: LIGHT_FRAME_INTERVAL_MS,
    });
  });

  it('draws everything on a GPU, or when the renderer is not reported, at the screen pixel ratio up to 2', () => {
    for (const name of [GPU, undefined]) {
      const profile = chooseRenderProfile('auto', name, 3);
      expect(profile).toMatchObject({ name: 'full', antialias: true, shadows: true });
      expect(profile.pixelRatio).toBe(2);
      expect(profile.minFrameIntervalMs).toBe(0);
    }
    expect(chooseRenderProfile('auto', GPU, 1.5).pixelRatio).toBe(1.5);
  });

  it('follows ?render=full and ?render=light whatever the renderer', () => {
    expect(chooseRenderProfile('full', SWIFTSHADER, 1)).toMatchObject({
      name: 'full',
      reason: '?render=full',
    });
    expect(chooseRenderProfile('light', GPU, 1)).toMatchObject({
      name: 'light',
      reason: '?render=light',
    });
  });

  it('reads ?render= from the URL, auto for anything else', () => {
    expect(readUrlSettings('?render=light').render).toBe('light');
    expect(readUrlSettings('?map=maze&render=full').render).toBe('full');
    expect(readUrlSettings('').render).toBe('auto');
    expect(readUrlSettings('?render=fast').render).toBe('auto');
    expect(readUrlSettings('?render=LIGHT').render).toBe('auto');
  });
});
