// The demo as a headless snapshot sees it: `chromium --headless --screenshot
// --virtual-time-budget=8000 URL`, the command line of a CI snapshot, a link preview or a user's
// bug report, with no page driven by a test. The 3D view must be drawn in that picture: the
// arena's floor, not the empty page behind the canvas. Saves it to artifacts/sim-demo-headless.png.
import { spawn } from 'node:child_process';
import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import sharp from 'sharp';
import { describe, expect, inject, it } from 'vitest';
import { CHROMIUM_FLAGS, requireChromium } from './chromium.js';

const artifacts = fileURLToPath(new URL('../../artifacts', import.meta.url));

/** The window the snapshot is taken in, px. */
const WINDOW = { width: 1400, height: 900 };
/**
 * A part of the 3D view in that window (the left column under the header, clear of the hint, the
 * minimap and the status line), where the framed arena's floor fills most of the picture.
 */
const VIEW_REGION = { left: 100, top: 150, width: 600, height: 400 };
/** The floor (#f3efe6) as the light render profile's lights draw it, and how far off a pixel may be. */
const FLOOR = { rgb: [217, 213, 205], tolerance: 24 } as const;
/** How long Chromium may take for the whole snapshot (load, 8 s of virtual time, the picture). */
const SNAPSHOT_TIMEOUT_MS = 90_000;

/** Runs Chromium's own `--screenshot` on `url` into `file`, as a command line does. */
function snapshot(url: string, file: string): Promise<void> {
  const profile = mkdtempSync(join(tmpdir(), 'headless-snapshot-profile-'));
  const args = [
    ...CHROMIUM_FLAGS,
    `--user-data-dir=${profile}`,
    `--window-size=${WINDOW.width},${WINDOW.height}`,
    `--screenshot=${file}`,
    '--virtual-time-budget=8000',
    url,
  ];
  return new Promise<void>((resolve, reject) => {
    const child = spawn(requireChromium(), args, { stdio: ['ignore', 'pipe', 'pipe'] });
    let output = '';
    child.stdout.on('data', (chunk: Buffer) => (output += chunk.toString()));
    child.stderr.on('data', (chunk: Buffer) => (output += chunk.toString()));
    const timer = setTimeout(() => {
      child.kill('SIGKILL');
      reject(new Error(`chromium --screenshot did not finish within ${SNAPSHOT_TIMEOUT_MS} ms`));
    }, SNAPSHOT_TIMEOUT_MS);
    child.once('error', (error) => {
      clearTimeout(timer);
      reject(error);
    });
    child.once('close', (code, signal) => {
      clearTimeout(timer);
      if (code === 0) resolve();
      else
        reject(
          new Error(`chromium --screenshot exited (${code ?? signal}):\n${output.slice(-4000)}`),
        );
    });
  }).finally(() => rmSync(profile, { recursive: true, force: true }));
}

interface RegionStats {
  pixels: number;
  /** The share of the region's most common colour, 0..1. */
  commonestShare: number;
  /** The share of pixels within the floor's tolerance, 0..1. */
  floorShare: number;
}

/** Colour statistics of `region` of the PNG `file`. */
async function regionStats(file: string, region: typeof VIEW_REGION): Promise<RegionStats> {
  const { data, info } = await sharp(file)
    .extract(region)
    .removeAlpha()
    .raw()
    .toBuffer({ resolveWithObject: true });
  const counts = new Map<number, number>();
  let floor = 0;
  for (let i = 0; i < data.length; i += info.channels) {
    const r = data[i] ?? 0;
    const g = data[i + 1] ?? 0;
    const b = data[i + 2] ?? 0;
    const key = (r << 16) | (g << 8) | b;
    counts.set(key, (counts.get(key) ?? 0) + 1);
    const [fr, fg, fb] = FLOOR.rgb;
    const near = (x: number, y: number) => Math.abs(x - y) <= FLOOR.tolerance;
    if (near(r, fr) && near(g, fg) && near(b, fb)) floor += 1;
  }
  const pixels = data.length / info.channels;
  return {
    pixels,
    commonestShare: Math.max(...counts.values()) / pixels,
    floorShare: floor / pixels,
  };
}

describe('apps/sim-demo in a headless snapshot (chromium --headless --screenshot)', () => {
  it(
    'draws the 3D view: the arena floor fills the view, not the empty page',
    async () => {
      mkdirSync(artifacts, { recursive: true });
      const file = join(artifacts, 'sim-demo-headless.png');
      rmSync(file, { force: true });
      await snapshot(`${inject('demoUrl')}?map=obstacles`, file);
      const stats = await regionStats(file, VIEW_REGION);
      // An undrawn view is one colour, the page's background, over all of the region.
      expect(stats.commonestShare, `the 3D view is one colour: ${file}`).toBeLessThan(0.9);
      expect(stats.floorShare, `the floor fills a fifth of the 3D view: ${file}`).toBeGreaterThan(
        0.2,
      );
    },
    SNAPSHOT_TIMEOUT_MS + 10_000,
  );
});
