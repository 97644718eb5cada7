// The browser demo's 3D view drawn in software: headless Chromium with --disable-gpu (WebGL by
// SwiftShader), as on a machine without a GPU. The full render profile (`?render=full`) beside
// the light one the page picks there by itself (`?render=auto`), in interleaved rounds, each on a
// fresh browser: the CPU that Chromium's processes take (from /proc) and the frames of the view
// drawn, with three robots in the arena, one turning in place.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { chromium } from 'playwright-core';
import { requireChromium } from '../tests/e2e/chromium.js';
import { serveBuiltDemo } from '../tests/e2e/demo-server.js';
import { reportFigure } from './report/figures.js';

const ROUNDS = 3;
const WARM_MS = 1500;
const MEASURE_MS = 6000;
const CHROMIUM = requireChromium();
const TICKS_PER_SECOND = Number(execFileSync('getconf', ['CLK_TCK'], { encoding: 'utf8' }));

/** CPU seconds used so far by the process tree under the process whose command line has `mark`. */
function treeCpuSeconds(mark: string): number {
  const parent = new Map<number, number>();
  const cpu = new Map<number, number>();
  const roots: number[] = [];
  for (const entry of readdirSync('/proc')) {
    if (!/^\d+$/.test(entry)) continue;
    const pid = Number(entry);
    try {
      // Fields after the command name: state ppid ... utime (14th field) stime (15th).
      const fields = readFileSync(`/proc/${pid}/stat`, 'utf8').split(') ')[1]?.split(' ') ?? [];
      parent.set(pid, Number(fields[1]));
      cpu.set(pid, (Number(fields[11]) + Number(fields[12])) / TICKS_PER_SECOND);
      if (readFileSync(`/proc/${pid}/cmdline`, 'utf8').includes(mark)) roots.push(pid);
    } catch {
      // the process ended while being read
    }
  }
  const inTree = (pid: number): boolean => {
    for (let p: number | undefined = pid; p !== undefined && p > 1; p = parent.get(p)) {
      if (roots.includes(p)) return true;
    }
    return false;
  };
  let total = 0;
  for (const [pid, seconds] of cpu) if (inTree(pid)) total += seconds;
  return total;
}

interface Sample {
  cores: number;
  fps: number;
}

async function measure(url: string, render: 'full' | 'auto'): Promise<Sample> {
  const profile = mkdtempSync(join(tmpdir(), 'demo-render-profile-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    viewport: { width: 1400, height: 900 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run'],
  });
  try {
    const page = context.pages()[0] ?? (await context.newPage());
    await page.goto(`${url}?map=empty&speed=20&robots=3&render=${render}`, { timeout: 20_000 });
    // Functions run in the page name the hooks inline: they cannot reach this module's scope.
    await page.waitForFunction(() => 'simDemo' in window, undefined, { timeout: 15_000 });
    await page.locator('#viewport > canvas').focus();
    await page.keyboard.down('ArrowLeft'); // the selected robot turns in place for as long as held
    await page.waitForTimeout(WARM_MS);
    const frames = () =>
      page.evaluate(() =>
        (window as unknown as { simDemo: { framesDrawn(): number } }).simDemo.framesDrawn(),
      );
    const f0 = await frames();
    const c0 = treeCpuSeconds(profile);
    const t0 = performance.now();
    await page.waitForTimeout(MEASURE_MS);
    const seconds = (performance.now() - t0) / 1000;
    const cores = (treeCpuSeconds(profile) - c0) / seconds;
    const fps = ((await frames()) - f0) / seconds;
    return { cores, fps };
  } finally {
    await context.close();
    rmSync(profile, { recursive: true, force: true });
  }
}

const demo = await serveBuiltDemo();
const full: Sample[] = [];
const light: Sample[] = [];
try {
  for (let round = 0; round < ROUNDS; round += 1) {
    full.push(await measure(demo.url, 'full'));
    light.push(await measure(demo.url, 'auto'));
  }
} finally {
  await demo.close();
}

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)] ?? 0;
const fullCores = median(full.map((s) => s.cores));
const lightCores = median(light.map((s) => s.cores));
const fullFps = median(full.map((s) => s.fps));
const lightFps = median(light.map((s) => s.fps));
console.log(
  `demo view drawn in software (headless Chromium, SwiftShader), 3 robots, one turning, median of ` +
    `${ROUNDS} interleaved rounds of ${MEASURE_MS / 1000} s:`,
);
console.log(
  `  full profile:  ${fullCores.toFixed(2)} cores, ${fullFps.toFixed(1)} frames/s\n` +
    `  light profile: ${lightCores.toFixed(2)} cores, ${lightFps.toFixed(1)} frames/s ` +
    `(${(fullCores / lightCores).toFixed(1)}x less CPU)`,
);
reportFigure({
  bench: 'demo-render',
  name: 'Chromium CPU, demo in software WebGL, light profile',
  value: lightCores,
  unit: 'cores',
  better: 'lower',
  alternative: { name: 'full profile', value: fullCores },
  note: 'headless Chromium --disable-gpu, 1400x900, three robots, one turning in place',
});
reportFigure({
  bench: 'demo-render',
  name: 'frames of the 3D view drawn, demo in software WebGL, light profile',
  value: lightFps,
  unit: 'frames/s',
  better: 'higher',
  alternative: { name: 'full profile', value: fullFps },
  note: 'the light profile draws at most 5 frames/s',
});
