/* nl_tool.h - what every command-line tool (tools/CMD.c) does first: the
 * program start of the harness (out-of-memory exit, OpenBLAS's idle workers
 * stopped), SIGXFSZ ignored, stdout checked at exit. This is the tools'
 * code, not the library's: it decides how a program ends, which the library
 * never does. */
#ifndef NL_TOOL_H
#define NL_TOOL_H

/* `name` prefixes the tool's own messages ("noiselab render"); borrowed for
 * the program's life (a string literal).
 *  - SIGXFSZ is ignored: a write past the file size limit (ulimit -f) then
 *    fails with EFBIG like one on a full disk, the output's commit says so
 *    and its temporary is removed, instead of the signal killing the tool
 *    with the temporary left beside the output.
 *  - At exit, stdout is flushed and closed and checked (nl_stream_close): a
 *    result lost on a full disk or a closed pipe is one line
 *    "NAME: write error on standard output: REASON" and exit 2, the status
 *    of a failed output, whatever main returned.
 *  - NL_MEMAVAILABLE_OVERRIDE=BYTES, when set, caps the memory nl_mem_fits
 *    counts as available (nl_mem_cap): a test hook, so the suite can test a
 *    refusal at a size this machine could allocate. */
void nl_tool_start(const char *name);

/* A tool's refusal: prefix ("noiselab render: ") and the message as
 * nl_message prints it on stderr, then exit(2), the usage-error status. */
void nl_tool_die(const char *prefix, const char *fmt, ...)
  __attribute__((format(printf, 2, 3), noreturn));

/* Refuses, before any work, an output path that would replace
 *  - one of the command's inputs (n of them, NULL entries skipped): the same
 *    file (device and inode; for an output not made yet, the same resolved
 *    path). Devices and FIFOs are written through, never replaced: exempt;
 *  - a file of the sources this tool was built from: inside that tree,
 *    outside results/ (the committed results, written on purpose) and this
 *    build folder, a file git tracks there (`git ls-files --error-unmatch`);
 *    without git or a checkout, any existing file there outside build*
 *    folders. A rebuilt source folder would fail the next build.
 * One line "NAME: OUT: why" and exit 1. "-" (stdout) passes. */
void nl_tool_check_output(const char *out, const char *const *inputs, int n);

#endif
