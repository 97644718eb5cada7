// Where the doc-commands test runs a block: in a network of its own. The docs' commands name the
// default ports (nats://127.0.0.1:4222, --ws-port 8765, --udp-port 4210, the MCP server's 3333),
// and a machine that runs the README's services has them taken: the README's own
// `nats-server -a 127.0.0.1 &` holds 4222. So each block runs, as written, in a new network
// namespace with a loopback of its own (`unshare --map-root-user --net`: a user namespace, no
// root needed), where those ports are free whatever the machine runs, and where a block can
// reach no server of the machine's by mistake. Blocks then share no port either, and run side by
// side.
//
// A machine that gives no namespace (user namespaces switched off, no `ip` to bring the loopback
// up) runs the blocks on its own network, one at a time per port, as the test did before: the
// ports the blocks name must then be free, and the test says so when one is not.
import { spawnSync } from 'node:child_process';

/** Brings the new namespace's loopback up (it starts down): `ip` is in /usr/sbin or /sbin. */
const LOOPBACK_UP = 'PATH="$PATH:/usr/sbin:/sbin" ip link set lo up';

export interface BlockNetwork {
  /** True: each block gets a network of its own; false: blocks run on the machine's network. */
  own: boolean;
  /** Why the blocks run on the machine's network (the namespace's error), when they do. */
  reason?: string;
  /** The program and arguments that run the bash `script` there. */
  command(script: string): { file: string; args: string[] };
}

/** The namespace's command for `script`: the loopback brought up, then the script as it is. */
function inOwnNetwork(script: string): { file: string; args: string[] } {
  const up = `${LOOPBACK_UP} || { echo "doc-test: could not bring up the block's own loopback" >&2; exit 1; }`;
  // `unshare` runs bash in place (no fork), so the test's process group is the block's.
  return { file: 'unshare', args: ['--map-root-user', '--net', 'bash', '-c', `${up}\n${script}`] };
}

/** Probes whether this machine gives a block a network namespace with its loopback up. */
export function blockNetwork(): BlockNetwork {
  const tried = spawnSync('unshare', ['--map-root-user', '--net', 'sh', '-c', LOOPBACK_UP], {
    encoding: 'utf8',
    timeout: 10_000,
  });
  if (tried.status === 0) return { own: true, command: inOwnNetwork };
  const reason =
    tried.error?.message ??
    (tried.stderr.trim() || `unshare --map-root-user --net exited ${tried.status ?? tried.signal}`);
  return { own: false, reason, command: (script) => ({ file: 'bash', args: ['-c', script] }) };
}
