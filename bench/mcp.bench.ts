// Latency of one tool call (get_pose) through the MCP server, over stdio (the `hal mcp` process,
// its embedded simulator) and over streamable HTTP on 127.0.0.1 (this process, the same HAL as
// the direct call), beside a direct `locomotion.getPose()` on the HAL. Interleaved: each round
// makes one call of each kind, so load on the machine falls on all three alike.
import { fileURLToPath } from 'node:url';
import { Client } from '@modelcontextprotocol/sdk/client/index.js';
import { StdioClientTransport } from '@modelcontextprotocol/sdk/client/stdio.js';
import { StreamableHTTPClientTransport } from '@modelcontextprotocol/sdk/client/streamableHttp.js';
import { createRobotMcpServer, serveHttp } from '@hal/mcp';
import { SimulationHAL } from '@hal/simulation';
import { createToolExecutor } from '@hal/tools';
import { reportFigure } from './report/figures.js';

const ROUNDS = 400;
const WARMUP = 40;
const root = fileURLToPath(new URL('..', import.meta.url));

const hal = new SimulationHAL();
await hal.initialize();
const executor = createToolExecutor(hal);
const endpoint = await serveHttp(() => createRobotMcpServer(hal, executor), { port: 0 });

const http = new Client({ name: 'bench', version: '1.0.0' });
await http.connect(new StreamableHTTPClientTransport(new URL(endpoint.url)));
const stdio = new Client({ name: 'bench', version: '1.0.0' });
await stdio.connect(
  new StdioClientTransport({
    command: process.execPath,
    args: ['--conditions=@hal/source', '--import', 'tsx', 'packages/cli/src/main.ts', 'mcp'],
    cwd: root,
    stderr: 'ignore',
  }),
);

async function timed(work: () => Promise<unknown>): Promise<number> {
  const start = process.hrtime.bigint();
  await work();
  return Number(process.hrtime.bigint() - start) / 1000;
}

const samples = { direct: [] as number[], stdio: [] as number[], http: [] as number[] };
for (let i = 0; i < WARMUP + ROUNDS; i += 1) {
  const direct = await timed(() => hal.locomotion.getPose());
  const overStdio = await timed(() => stdio.callTool({ name: 'get_pose', arguments: {} }));
  const overHttp = await timed(() => http.callTool({ name: 'get_pose', arguments: {} }));
  if (i >= WARMUP) {
    samples.direct.push(direct);
    samples.stdio.push(overStdio);
    samples.http.push(overHttp);
  }
}
const check = await stdio.callTool({ name: 'get_pose', arguments: {} });
if (check.isError === true) throw new Error('get_pose over stdio failed');

function percentile(values: number[], p: number): number {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.min(sorted.length - 1, Math.floor((p / 100) * sorted.length))] ?? NaN;
}

const direct50 = percentile(samples.direct, 50);
const direct99 = percentile(samples.direct, 99);
console.log(
  `get_pose, ${ROUNDS} interleaved rounds; direct call: p50 ${direct50.toFixed(1)} us, p99 ${direct99.toFixed(1)} us`,
);
for (const transport of ['stdio', 'http'] as const) {
  for (const [label, p, directP] of [
    ['p50', 50, direct50],
    ['p99', 99, direct99],
  ] as const) {
    const value = percentile(samples[transport], p);
    console.log(
      `  MCP over ${transport.padEnd(5)} ${label}: ${value.toFixed(1).padStart(8)} us  (${(value / directP).toFixed(0)}x the direct call)`,
    );
    reportFigure({
      bench: 'mcp',
      name: `tool call over ${transport} ${label}`,
      value: Math.round(value * 10) / 10,
      unit: 'us',
      better: 'lower',
      alternative: { name: `direct getPose ${label}`, value: Math.round(directP * 10) / 10 },
    });
  }
}

await stdio.close();
await http.close();
await endpoint.close();
await hal.cleanup();
