/**
 * Resolves `{ value }` once `work` does, or `undefined` once `ms` have passed, whichever comes
 * first; a rejection of `work` before then passes through. The timer never outlives the wait.
 */
export async function withTimeout<T>(
  work: Promise<T>,
  ms: number,
): Promise<{ value: T } | undefined> {
  let timer: ReturnType<typeof setTimeout> | undefined;
  const expired = new Promise<undefined>((resolve) => {
    timer = setTimeout(() => resolve(undefined), ms);
  });
  try {
    return await Promise.race([work.then((value) => ({ value })), expired]);
  } finally {
    clearTimeout(timer);
  }
}
