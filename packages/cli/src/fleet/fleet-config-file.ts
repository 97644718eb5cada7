// `hal fleet --config <file>`: the devices from a JSON file in the device manager's own config
// format (simulated, physical over UDP or serial, and NATS devices), checked by its zod schema so
// a bad file is refused with every problem named by its path.
import { readFile } from 'node:fs/promises';
import { parseFleetConfig } from '@hal/fleet/node';
import type { FleetConfig } from '@hal/fleet/node';
import { errorMessage } from '@hal/types';
import { CliError } from '../cli-error.js';

/**
 * Reads and checks a fleet config file. A missing file is NOT_FOUND, text that is not JSON is
 * USAGE, and a config the schema refuses is the manager's INVALID_PARAMETER (issues by path).
 */
export async function readFleetConfigFile(path: string): Promise<FleetConfig> {
  let text: string;
  try {
    text = await readFile(path, 'utf8');
  } catch (error) {
    const reason = errorMessage(error);
    throw new CliError('NOT_FOUND', `--config ${path}: cannot read it (${reason})`);
  }
  let raw: unknown;
  try {
    raw = JSON.parse(text) as unknown;
  } catch (error) {
    const reason = errorMessage(error);
    throw new CliError('USAGE', `--config ${path}: not JSON (${reason})`);
  }
  return parseFleetConfig(raw);
}

/**
 * The config narrowed to the devices named with --device (all of them when none is named); a
 * name the file does not have is a USAGE error listing the ones it has.
 */
export function selectDevices(config: FleetConfig, ids: readonly string[]): FleetConfig {
  if (ids.length === 0) return config;
  const known = config.devices.map((d) => d.id);
  const unknown = ids.filter((id) => !known.includes(id));
  if (unknown.length > 0) {
    throw new CliError(
      'USAGE',
      `--device ${unknown.join(', ')}: not in the config file (it has ${known.join(', ') || 'no devices'})`,
    );
  }
  return { ...config, devices: config.devices.filter((d) => ids.includes(d.id)) };
}
