/* Configure-time probe (tests/fuzz/meson.build): links only when clang has
 * libFuzzer and the sanitizer runtimes. */
#include <stddef.h>
#include <stdint.h>
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { (void)data; (void)size; return 0; }
