// How `hal agent` shows a run to people: the model's reply streamed as it is generated, then one
// line per tool call and result, as they happen.
import type { AgentEvent } from '@hal/agent';

const clip = (text: string, n = 200) => (text.length > n ? `${text.slice(0, n)}...` : text);

/** Writes the events of one run to `write`, keeping track of a streamed line in progress. */
export function eventPrinter(write: (text: string) => void): (event: AgentEvent) => void {
  let streaming = false;
  const line = (text: string) => {
    if (streaming) write('\n');
    streaming = false;
    write(`${text}\n`);
  };
  return (e) => {
    switch (e.type) {
      case 'step_started':
        line(`step ${e.step} (${(e.elapsedMs / 1000).toFixed(1)} s)`);
        return;
      case 'token':
        if (!streaming) write('  model: ');
        streaming = true;
        write(e.text);
        return;
      case 'usage':
        line(
          e.completionTokens === undefined
            ? `  (${e.durationMs} ms)`
            : `  (${e.promptTokens} prompt tokens read, ${e.completionTokens} generated, ${(e.durationMs / 1000).toFixed(1)} s${e.tokensPerSecond === undefined ? '' : `, ${e.tokensPerSecond.toFixed(1)} tokens/s`})`,
        );
        return;
      case 'assistant_text':
        line(`  says: ${clip(e.text)}`);
        return;
      case 'tool_call':
        line(`  call ${e.name} ${e.arguments}`);
        return;
      case 'tool_result':
        line(
          `  ${e.isError ? 'error' : 'result'} ${e.name}${e.code === undefined ? '' : ` ${e.code}`}: ${clip(e.text)}${e.image ? ' [image]' : ''}`,
        );
        return;
      case 'context_trimmed':
        line(
          `  context full: ${e.droppedMessages} older messages left out (${e.promptTokens} of ${e.contextTokens} tokens)`,
        );
        return;
      case 'retry':
        line(`  retry ${e.attempt} in ${e.delayMs} ms: ${clip(e.reason)}`);
        return;
      case 'error':
        line(`  model error ${e.error.code}: ${clip(e.error.message)}`);
        return;
      case 'done':
        line(
          `done: ${e.reason} after ${e.steps} step${e.steps === 1 ? '' : 's'}, ${(e.elapsedMs / 1000).toFixed(1)} s`,
        );
        return;
    }
  };
}
