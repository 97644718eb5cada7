// A model that never answered is a failure of the model, not a score: real sockets (a closed
// port on 127.0.0.1, a host under .invalid that no resolver knows) and a preparation that fails.
import { createServer } from 'node:net';
import type { AddressInfo } from 'node:net';
import { describe, expect, it } from 'vitest';
import { builtinTasks } from '../builtin-tasks.js';
import { oracleAgent } from './oracle.js';
import { runEval } from '../run-eval.js';
import { summaryTable } from '../report/table.js';
import { markdownReport } from '../report/markdown.js';
import { runTrial } from '../trial.js';
import { chatAgent } from './chat.js';

/** A port on 127.0.0.1 that nothing listens on: taken, then let go. */
async function closedPort(): Promise<number> {
  const server = createServer();
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address() as AddressInfo;
  await new Promise<void>((resolve) => server.close(() => resolve()));
  return port;
}

const task = builtinTasks(['precision']).find((t) => t.id === 'precision/drive-30cm');
if (task === undefined) throw new Error('no precision/drive-30cm');

describe('a chat agent whose model never answers', () => {
  it('is a model failure naming ECONNREFUSED when the endpoint port is closed, with no check judged', async () => {
    const port = await closedPort();
    const agent = chatAgent({
      name: 'openai:m',
      endpoint: { baseUrl: `http://127.0.0.1:${port}/v1`, model: 'm' },
    });
    const { score } = await runTrial(task, 1, agent);
    expect(score.success).toBe(false);
    expect(score.failures).toEqual([]);
    expect(score.modelFailure?.code).toBe('NETWORK');
    expect(score.modelFailure?.message).toContain(`ECONNREFUSED 127.0.0.1:${port}`);
  }, 30_000);

  it('names ENOTFOUND for a host no resolver knows', async () => {
    const agent = chatAgent({
      name: 'openai:m',
      endpoint: { baseUrl: 'http://no-such-model-host.invalid/v1', model: 'm' },
    });
    const { score } = await runTrial(task, 1, agent);
    expect(score.modelFailure?.code).toBe('NETWORK');
    expect(score.modelFailure?.message).toContain('ENOTFOUND');
    expect(score.modelFailure?.message).toContain('no-such-model-host.invalid');
  }, 30_000);

  it("is a model failure with the provider's own code when its preparation fails (a grammar it cannot build)", async () => {
    const refused = Object.assign(new Error('llama.cpp refused the grammar'), {
      code: 'SCHEMA_UNSUPPORTED',
    });
    const agent = chatAgent({
      name: 'local:x',
      provider: { name: 'x', complete: () => Promise.reject(new Error('never asked')) },
      prepare: () => Promise.reject(refused),
    });
    const { score } = await runTrial(task, 1, agent);
    expect(score.modelFailure).toEqual({
      code: 'SCHEMA_UNSUPPORTED',
      message: 'llama.cpp refused the grammar',
    });
    expect(score.toolCalls).toBe(0);
  });

  it('is left out of the rates; its remaining trials are not run; the others score as ever', async () => {
    const port = await closedPort();
    const agent = chatAgent({
      name: 'openai:m',
      endpoint: { baseUrl: `http://127.0.0.1:${port}/v1`, model: 'm' },
    });
    const tasks = builtinTasks(['precision']).slice(0, 2);
    const report = await runEval({ tasks, agents: [oracleAgent(), agent], trials: 3 });
    const [oracle, model] = report.scores.agents;
    expect(oracle?.modelFailure).toBeNull();
    expect(oracle?.overall).toMatchObject({ successes: 6, trials: 6 });
    expect(model?.trials).toHaveLength(1);
    expect(model?.overall.trials).toBe(0);
    expect(model?.modelFailure).toMatchObject({ code: 'NETWORK', trials: 1, notRun: 5 });
    const table = summaryTable(report);
    expect(table).toMatch(/\noracle\s.*\sok$/m);
    expect(table).toMatch(
      /\nopenai:m\s+-\s+-\s+-\s+-\s+\d+\s+0\s+0\s+model failed \(NETWORK\) in 1 trial, 5 not run$/,
    );
    expect(table.split('\n').at(-1)).not.toContain('%');
    const markdown = markdownReport(report);
    expect(markdown).toContain(
      '**The model could not be used** in 1 trial(s) (then 5 more were not run): NETWORK:',
    );
    expect(markdown.match(/ECONNREFUSED/g)).toHaveLength(1);
  }, 60_000);

  it('a model that answered is scored, even when it fails the task', async () => {
    const agent = chatAgent({
      name: 'scripted',
      provider: {
        name: 'scripted',
        complete: () =>
          Promise.resolve({ text: 'I will not move.', refusal: undefined, toolCalls: [] }),
      },
    });
    const report = await runEval({ tasks: [task], agents: [agent], trials: 1 });
    const [row] = report.scores.agents;
    expect(row?.modelFailure).toBeNull();
    expect(row?.overall).toMatchObject({ successes: 0, trials: 1 });
    expect(summaryTable(report)).not.toContain('model');
  });
});
