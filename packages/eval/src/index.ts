export { builtinTasks } from './builtin-tasks.js';
export {
  COLOURS,
  ObjectSchema,
  TASK_FILE_VERSION,
  TASK_GROUPS,
  TaskFileSchema,
  TaskSchema,
  WorldSchema,
} from './task-schema.js';
export type { Task, TaskGroup, TaskObject } from './task-schema.js';
export { loadTaskFile } from './task-load.js';
export { loadWorldFile, parseWorldFile, realiseWorld } from './world-file.js';
export type { RealisedWorld, TaskWorld } from './world-file.js';
export type { TaskVariant } from './variant.js';
export type { AgentAnswer, AgentTrial, EvalAgent, ModelFailure } from './agent.js';
export { oracleAgent } from './agents/oracle.js';
export { claimerAgent, naiveAgent, straightAgent } from './agents/baselines.js';
export type { InstrumentedHal, TrialInfo, TrialOptions, TrialScore, TrialTiming } from './trial.js';
export type { EvalRobot, StagedRobot } from './robot-trial.js';
export type { TruePoseSource } from './bodies/staged-body.js';
export type { GroupSummary, Rate, TaskSummary } from './scores.js';
export { runEval } from './run-eval.js';
export type { AgentModelFailure, AgentScores, EvalOptions, EvalReport } from './run-eval.js';
export { EvalError } from './errors.js';
export type { EvalErrorCode } from './errors.js';
export { chatAgent } from './agents/chat.js';
export type { ChatAgentOptions } from './agents/chat.js';
export { modelFailureNote, summaryTable } from './report/table.js';
export { markdownReport } from './report/markdown.js';
export { successSvg } from './report/svg.js';
export { navigationAgent } from './agents/navigation.js';
export type { NavigationAgentOptions } from './agents/navigation.js';
export { cameraNavigationAgent } from './agents/camera-navigation.js';
export { parserAgent } from './agents/parser.js';
export type { CameraNavigationAgentOptions } from './agents/camera-navigation.js';
export { RealitySchema } from './reality.js';
export type { RealityInput } from './reality.js';
export { intervalOverTasks } from './interval.js';
export type { IntervalOptions, TaskCount, TaskIntervalMethod } from './interval.js';
export { passHatK } from './pass-k.js';
export type { PassK } from './pass-k.js';
export { rateOverTasks } from './scores.js';
export type { RateOverTasks } from './scores.js';
