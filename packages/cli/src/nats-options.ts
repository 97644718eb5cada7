// The NATS options every networked subcommand shares, with their environment defaults, so
// `hal status`, `hal test`, `hal fleet` and `hal serve --nats` reach a server the same way.
import { Option } from 'commander';
import type { Command } from 'commander';
import type { NatsConnectOptions } from '@hal/nats';
import { usageError } from './values.js';

/** The parsed NATS options (before environment defaults). */
export interface NatsCliOptions {
  nats?: string;
  natsUser?: string;
  natsPass?: string;
  natsToken?: string;
  natsCa?: string;
  natsCert?: string;
  natsKey?: string;
}

/** A device id as it appears in a subject token: no dots, spaces or wildcards. */
export function deviceIdArg(value: string): string {
  if (!/^[A-Za-z0-9_-]{1,64}$/.test(value)) {
    throw usageError(
      `a device id is 1-64 letters, digits, '-' or '_' (it is a NATS subject token), got "${value}"`,
    );
  }
  return value;
}

/** Adds --nats, the credentials and TLS files to `command`. */
export function addNatsOptions(command: Command): Command {
  return command
    .addOption(
      new Option(
        '--nats <servers>',
        'NATS server(s), comma-separated (default $NATS_URL, else nats://127.0.0.1:4222)',
      ),
    )
    .addOption(new Option('--nats-user <user>', 'NATS user (default $NATS_USER)'))
    .addOption(new Option('--nats-pass <password>', 'NATS password (default $NATS_PASS)'))
    .addOption(new Option('--nats-token <token>', 'NATS token (default $NATS_TOKEN)'))
    .addOption(new Option('--nats-ca <file>', 'CA certificate for a TLS server'))
    .addOption(new Option('--nats-cert <file>', 'client certificate for TLS'))
    .addOption(new Option('--nats-key <file>', 'client key for TLS'));
}

/** Turns the parsed options and the environment into `@hal/nats` connection options. */
export function natsConnectOptions(
  options: NatsCliOptions,
  env: Readonly<Record<string, string | undefined>>,
  name = 'hal-cli',
): NatsConnectOptions {
  const servers = (options.nats ?? env.NATS_URL ?? 'nats://127.0.0.1:4222')
    .split(',')
    .map((s) => s.trim())
    .filter((s) => s !== '');
  const result: NatsConnectOptions = { servers, name };
  const user = options.natsUser ?? env.NATS_USER;
  const pass = options.natsPass ?? env.NATS_PASS;
  const token = options.natsToken ?? env.NATS_TOKEN;
  if (user !== undefined) result.user = user;
  if (pass !== undefined) result.pass = pass;
  if (token !== undefined) result.token = token;
  if (
    options.natsCa !== undefined ||
    options.natsCert !== undefined ||
    options.natsKey !== undefined
  ) {
    result.tls = {
      ...(options.natsCa !== undefined ? { caFile: options.natsCa } : {}),
      ...(options.natsCert !== undefined ? { certFile: options.natsCert } : {}),
      ...(options.natsKey !== undefined ? { keyFile: options.natsKey } : {}),
    };
  }
  return result;
}
