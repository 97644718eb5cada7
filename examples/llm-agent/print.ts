// One line per agent event, for a terminal.
import type { AgentEvent } from '@hal/agent';

const clip = (text: string, n = 160) => (text.length > n ? `${text.slice(0, n)}...` : text);

/** The line for an event; none for streamed tokens (the caller may print them as they come). */
export function describeEvent(e: AgentEvent): string | undefined {
  switch (e.type) {
    case 'token':
      return undefined;
    case 'usage':
      return e.completionTokens === undefined
        ? `  model answered in ${e.durationMs} ms`
        : `  model: ${e.promptTokens} prompt + ${e.completionTokens} generated tokens in ${e.durationMs} ms`;
    case 'context_trimmed':
      return `  context full: ${e.droppedMessages} older messages left out (${e.promptTokens}/${e.contextTokens} tokens)`;
    case 'step_started':
      return `step ${e.step} (${(e.elapsedMs / 1000).toFixed(1)} s)`;
    case 'assistant_text':
      return `  model: ${clip(e.text)}`;
    case 'tool_call':
      return `  call ${e.name} ${e.arguments}`;
    case 'tool_result':
      return `  ${e.isError ? 'error' : 'result'} ${e.name}${e.code === undefined ? '' : ` ${e.code}`}: ${clip(e.text)}${e.image ? ' [image]' : ''}`;
    case 'retry':
      return `  retry ${e.attempt} in ${e.delayMs} ms: ${clip(e.reason)}`;
    case 'error':
      // not clipped: the URL and the cause are at its end
      return `  endpoint error ${e.error.code}: ${e.error.message}`;
    case 'done':
      return `done: ${e.reason} after ${e.steps} step${e.steps === 1 ? '' : 's'}, ${(e.elapsedMs / 1000).toFixed(1)} s`;
  }
}
