// `hal discover`: lists the robots that announce themselves with mDNS (_hal-cube._udp).
import { Option } from 'commander';
import { DEFAULT_DISCOVERY_TIMEOUT_MS, discoverRobots } from '@hal/discovery';
import type { DiscoverOptions } from '@hal/discovery';
import { formatRobots } from '../discover/format.js';
import { ipv4Arg } from '../discover/options.js';
import { integerArg } from '../values.js';
import { emit, progress } from '../io.js';
import { cliLogger } from '../logger.js';
import type { RegisterCommand } from './context.js';

interface DiscoverCliOptions {
  timeout: number;
  interface?: string;
}

export const registerDiscover: RegisterCommand = (program, { io, global }) => {
  program
    .command('discover')
    .description('list the robots on the local network (mDNS _hal-cube._udp), within --timeout')
    .addOption(
      new Option('--timeout <ms>', 'how long to listen, ms (1..60000)')
        .argParser(integerArg('--timeout', 1, 60_000))
        .default(DEFAULT_DISCOVERY_TIMEOUT_MS),
    )
    .addOption(
      new Option(
        '--interface <address>',
        'IPv4 address of the network interface to search on (default: the system default)',
      ).argParser(ipv4Arg('--interface')),
    )
    .action(async (options: DiscoverCliOptions) => {
      const g = global();
      // a skipped (malformed) announcement is a warning on stderr: a JSON log line with --json,
      // as every command writes its warnings
      const json = cliLogger(io, true);
      const logger: NonNullable<DiscoverOptions['logger']> = {
        log: (level, namespace, message) => {
          if (g.json) json.log(level, namespace, message);
          else if (level === 'warn' || level === 'error') io.err(`hal discover: ${message}\n`);
        },
      };
      progress(io, g, `listening for robots for ${options.timeout} ms...`);
      const robots = await discoverRobots({
        timeoutMs: options.timeout,
        logger,
        signal: io.signal,
        ...(options.interface === undefined ? {} : { mdns: { interface: options.interface } }),
      });
      if (g.json) {
        for (const robot of robots) emit(io, g, robot, () => '');
      } else {
        emit(io, g, robots, () => formatRobots(robots, options.timeout));
      }
    });
};
