/* nl_tool.c - the tools' common start (nl_tool.h). */
#include "nl_tool.h"

#include "harness/nl_harness.h"

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static const char *tool_name = "noiselab";

/* atexit: registered before any output's clean-up (nl_atomic_open registers
 * its own on first use), so it runs last, once the temporaries are gone. */
static void tool_close_stdout(void)
{
  nl_error err;
  if (nl_stream_close(stdout, "standard output", &err)) {
    nl_message(stderr, "%s: %s", tool_name, err.msg);
    _exit(2);
  }
}

void nl_tool_start(const char *name)
{
  tool_name = name;
  nl_harness_program_start();
  signal(SIGXFSZ, SIG_IGN);
  atexit(tool_close_stdout);
}
