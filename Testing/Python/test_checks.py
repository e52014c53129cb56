"""The pvpython tests' check lines: one printed line per check, failures
remembered for the exit code; and the ending of the tests that run under
pvbatch --mpi."""

import sys

failures = []


def check(condition, message):
    """Prints one result line and remembers a failure."""
    print(("ok     " if condition else "FAILED ") + message, flush=True)
    if not condition:
        failures.append(message)
    return condition


def summary(failed):
    """Prints each failure of `failed` and the "N failed" line CTest
    matches; returns the exit status (1 on a failure)."""
    for failure in failed:
        print("FAILED " + failure)
    print("%d failed" % len(failed))
    return 1 if failed else 0


def run_on_every_rank(main, usage, argument_counts):
    """Calls main(*arguments) when the script has one of `argument_counts`
    arguments (else prints `usage`), and exits only on a failure: under
    pvbatch --mpi the script runs on rank 0 only, and sys.exit there skips
    the final barrier, so the other ranks are killed. The result is the
    "N failed" line."""
    if len(sys.argv) - 1 not in argument_counts:
        print(usage)
        sys.exit(2)
    status = main(*sys.argv[1:])
    if status:
        sys.exit(status)
