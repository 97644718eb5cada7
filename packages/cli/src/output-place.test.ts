import { existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import { checkOutputPlace, openRecordingFile } from './output-place.js';
import { usageErrorLike } from './usage-error.fixture.js';

const dir = mkdtempSync(join(tmpdir(), 'hal-output-place-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

/** The one usage error every parser throws, its message naming the option. */
const usage = usageErrorLike;

describe('checkOutputPlace', () => {
  it('takes a new file in a folder that exists, and replaces one only with overwrite', async () => {
    const file = join(dir, 'run.mcap');
    await expect(checkOutputPlace({ option: '-o', path: file, kind: 'file' })).resolves.toBe(file);
    writeFileSync(file, 'earlier run');
    await expect(checkOutputPlace({ option: '-o', path: file, kind: 'file' })).rejects.toThrow(
      usage(`"-o" ${file}: exists (give --overwrite to replace it)`),
    );
    await expect(
      checkOutputPlace({ option: '-o', path: file, kind: 'file', overwrite: true }),
    ).resolves.toBe(file);
    // a check changes nothing
    expect(readFileSync(file, 'utf8')).toBe('earlier run');
  });

  it('refuses a file whose folder is missing, a folder given as a file, and /proc', async () => {
    const missing = join(dir, 'no-such-dir', 'x.mcap');
    await expect(
      checkOutputPlace({ option: '--record', path: missing, kind: 'file' }),
    ).rejects.toThrow(
      usage(`"--record" ${missing}: its folder ${join(dir, 'no-such-dir')} does not exist`),
    );
    await expect(checkOutputPlace({ option: '--record', path: dir, kind: 'file' })).rejects.toThrow(
      usage(/is a folder, not a file/),
    );
    await expect(
      checkOutputPlace({ option: '--record', path: '/proc/run.mcap', kind: 'file' }),
    ).rejects.toThrow(
      usage('"--record" /proc/run.mcap: is on the proc filesystem, where nothing can be written'),
    );
    await expect(
      checkOutputPlace({ option: '--out', path: '/proc/eval/reports', kind: 'folder' }),
    ).rejects.toThrow(usage(/is on the proc filesystem/));
    expect(existsSync(join(dir, 'no-such-dir'))).toBe(false);
  });

  it('takes a folder that is new (parents too) or empty, another only with overwrite', async () => {
    const fresh = join(dir, 'reports', 'today');
    await expect(checkOutputPlace({ option: '--out', path: fresh, kind: 'folder' })).resolves.toBe(
      fresh,
    );
    expect(existsSync(join(dir, 'reports'))).toBe(false);
    const used = join(dir, 'used');
    mkdirSync(used);
    await expect(checkOutputPlace({ option: '--out', path: used, kind: 'folder' })).resolves.toBe(
      used,
    );
    writeFileSync(join(used, 'eval.json'), '{}');
    await expect(checkOutputPlace({ option: '--out', path: used, kind: 'folder' })).rejects.toThrow(
      usage(`"--out" ${used}: is not empty (give --overwrite to replace what is there)`),
    );
    await expect(
      checkOutputPlace({ option: '--out', path: used, kind: 'folder', overwrite: true }),
    ).resolves.toBe(used);
    const file = join(used, 'eval.json');
    await expect(checkOutputPlace({ option: '--out', path: file, kind: 'folder' })).rejects.toThrow(
      usage(`"--out" ${file}: exists and is not a folder`),
    );
  });

  it('refuses a folder it cannot write in, naming the errno', async () => {
    // root may write anywhere but on a read-only filesystem: /proc/sys is one either way
    const where = process.getuid?.() === 0 ? '/sys/x.mcap' : '/x.mcap';
    await expect(checkOutputPlace({ option: '-o', path: where, kind: 'file' })).rejects.toThrow(
      usage(
        new RegExp(`^"-o" ${where}: (is on the sys filesystem|cannot write in / \\(EACCES\\))`),
      ),
    );
  });
});

describe('openRecordingFile', () => {
  it('opens an MCAP recorder on a file that can be written, and refuses one that exists', async () => {
    const file = join(dir, 'opened.mcap');
    const recorder = await openRecordingFile({ option: '--record', path: file });
    await recorder.close();
    expect(readFileSync(file).subarray(1, 5).toString()).toBe('MCAP');
    await expect(openRecordingFile({ option: '--record', path: file })).rejects.toThrow(
      usage(/exists \(give --overwrite to replace it\)/),
    );
    const again = await openRecordingFile({ option: '--record', path: file, overwrite: true });
    await again.close();
  });
});
