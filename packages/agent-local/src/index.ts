export { createLocalChatProvider } from './local-provider.js';
export { defaultThreads } from './threads.js';
export type { LocalChatProvider, LocalChatProviderOptions } from './local-provider.js';
export { DEFAULT_MODEL_NAME, defaultModelFile, isDefaultModelFile } from './model-file.js';
export {
  LOCAL_SYSTEM_PROMPT,
  SKILL_EXAMPLES,
  SKILLS_SYSTEM_PROMPT,
  SMALL_MODEL_TOOLS,
  systemText,
} from './prompt.js';
export type { ExampleRun } from './example-run.js';
export { pullDefaultModel } from './model-pull.js';
export type { PulledModel, PullModelOptions } from './model-pull.js';
export { DEFAULT_MODEL_SOURCE } from './model-source.js';
export { LocalModelError } from './errors.js';
export type { LocalModelErrorCode } from './errors.js';
