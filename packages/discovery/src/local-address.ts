// Whether an address belongs to this machine: a robot announced from here (the emulator, whose
// announcer publishes this machine's addresses) is reached over loopback.
import { networkInterfaces } from 'node:os';

/** This machine's interface addresses (IPv6 without a zone). */
export function localAddresses(): Set<string> {
  const out = new Set<string>();
  for (const list of Object.values(networkInterfaces())) {
    for (const entry of list ?? []) out.add(entry.address.split('%')[0] ?? entry.address);
  }
  return out;
}

/** True when one of `addresses` is an address of this machine. */
export function isOnThisMachine(addresses: readonly string[]): boolean {
  const mine = localAddresses();
  return addresses.some((address) => mine.has(address.split('%')[0] ?? address));
}
