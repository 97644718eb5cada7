/* global process, console */
// A user's Node program, run with plain `node` (no tsx, no export conditions) from the temporary
// app the published tarballs are installed into. It imports every export of every package by
// name, drives SimulationHAL, and prints what it found as one JSON line for the test to check.
import { readFileSync } from 'node:fs';

const names = JSON.parse(process.argv[2] ?? '[]');

const imports = [];
for (const name of names) {
  const manifest = JSON.parse(readFileSync(`node_modules/${name}/package.json`, 'utf8'));
  for (const subpath of Object.keys(manifest.exports ?? {})) {
    const specifier = subpath === '.' ? name : `${name}/${subpath.slice(2)}`;
    try {
      const module = await import(specifier);
      imports.push({
        specifier,
        resolved: import.meta.resolve(specifier),
        exportCount: Object.keys(module).length,
      });
    } catch (error) {
      imports.push({ specifier, code: error.code, error: String(error.message) });
    }
  }
}

const { SimulationHAL } = await import('@hal/simulation');
const { PoseSchema } = await import('@hal/types');
const hal = new SimulationHAL();
await hal.initialize();
const before = PoseSchema.parse(await hal.locomotion.getPose());
const moved = await hal.locomotion.moveForward(10);
const after = PoseSchema.parse(await hal.locomotion.getPose());
const frame = await hal.vision.captureFrame();
await hal.cleanup();

console.log(JSON.stringify({ imports, before, after, moved, framePrefix: frame.slice(0, 23) }));
