// `hal fleet run`'s mode: --mode, else the config file's own `mode` when it names one that runs
// something (synchronized or leader-follower), else a usage error. Decided before any device is
// connected.
import { CliError } from '../cli-error.js';
import { readFleetConfigFile } from './fleet-config-file.js';

/** The modes `hal fleet run` runs. */
export const RUN_MODES = ['synchronized', 'leader-follower'] as const;
export type RunMode = (typeof RUN_MODES)[number];

const isRunMode = (mode: string): mode is RunMode =>
  (RUN_MODES as readonly string[]).includes(mode);

/** The mode to run: `given` (--mode), else the one the config file at `configPath` names. */
export async function resolveRunMode(
  given: RunMode | undefined,
  configPath: string | undefined,
): Promise<RunMode> {
  if (given !== undefined) return given;
  if (configPath === undefined) {
    throw new CliError(
      'USAGE',
      'give --mode synchronized or --mode leader-follower (or a --config file whose "mode" is one of them)',
    );
  }
  const { mode } = await readFleetConfigFile(configPath);
  if (isRunMode(mode)) return mode;
  throw new CliError(
    'USAGE',
    `--config ${configPath}: its mode is "${mode}", which runs nothing by itself; give --mode synchronized or --mode leader-follower`,
  );
}
