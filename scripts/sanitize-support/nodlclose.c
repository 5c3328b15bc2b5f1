/* SPDX-License-Identifier: BSD-3-Clause
 * Preloaded by scripts/sanitize: dlclose() that keeps the library mapped.
 * Mesa unloads its DRI driver (swrast_dri.so) when the last GL context
 * goes; LeakSanitizer then finds the driver's two 56-byte one-time
 * allocations in an unmapped module it can neither name nor suppress.
 * Kept mapped, the driver's globals still reference them and nothing is
 * reported; a leak through our code still is. */
int dlclose(void* handle)
{
  (void)handle;
  return 0;
}
