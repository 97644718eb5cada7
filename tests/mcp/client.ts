// Shared by the MCP tests: the server process's command line, and what a call answers.
import { fileURLToPath } from 'node:url';
import type { Client } from '@modelcontextprotocol/sdk/client/index.js';

export const REPO_ROOT = fileURLToPath(new URL('../..', import.meta.url));

/** The embedded simulator's clock speed-up in these tests (hal mcp --sim --time-scale). */
const SIM_SPEED_UP = ['--sim', '--time-scale', '20'];

/** Runs `hal mcp` from source, as `pnpm hal mcp` does. */
export function serverCommand(args: string[] = []): {
  command: string;
  args: string[];
  cwd: string;
} {
  return {
    command: process.execPath,
    args: [
      '--conditions=@hal/source',
      '--import',
      'tsx',
      'packages/cli/src/main.ts',
      'mcp',
      // the simulator runs on the real-time clock, as for a user; a test speeds it up
      ...(args.some((arg) => arg === '--udp' || arg === '--serial') ? [] : SIM_SPEED_UP),
      ...args,
    ],
    cwd: REPO_ROOT,
  };
}

export interface CallAnswer {
  isError: boolean;
  text: string;
  json: Record<string, unknown>;
  images: Array<{ data: string; mimeType: string }>;
}

/** Calls a tool and sorts out its content. */
export async function callTool(
  client: Client,
  name: string,
  args?: Record<string, unknown>,
): Promise<CallAnswer> {
  const result = await client.callTool({
    name,
    ...(args === undefined ? {} : { arguments: args }),
  });
  const content = result.content as Array<Record<string, unknown>>;
  const text = String(content.find((c) => c['type'] === 'text')?.['text'] ?? '');
  return {
    isError: result.isError === true,
    text,
    json: text === '' ? {} : (JSON.parse(text) as Record<string, unknown>),
    images: content
      .filter((c) => c['type'] === 'image')
      .map((c) => ({ data: String(c['data']), mimeType: String(c['mimeType']) })),
  };
}
