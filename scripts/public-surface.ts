// Writes tests/structure/public-surface.json: the names each package's entries export.
// Run it when a package's public surface changes on purpose; tests/structure/public-surface.test.ts
// fails until the file and the source agree.
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import {
  formatSurface,
  readPublicSurface,
  SURFACE_FILE,
} from '../tests/structure/public-surface.js';

const root = fileURLToPath(new URL('../', import.meta.url));
const surface = readPublicSurface(root);
writeFileSync(join(root, SURFACE_FILE), formatSurface(surface));
const counts = Object.entries(surface).map(
  ([name, byEntry]) =>
    `${name}: ${Object.values(byEntry).reduce((sum, names) => sum + Object.keys(names).length, 0)}`,
);
console.log(`wrote ${SURFACE_FILE}\n${counts.join('\n')}`);
