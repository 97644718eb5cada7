// The command-line pieces other programs (the `hal` command) share with hal-serve.
export {
  DEFAULT_ROBOT_UDP_PORT,
  hexKeyArg,
  hostPortArg,
  integerArg,
  positiveArg,
} from './values.js';
export { checkBinding } from '../server/auth.js';
