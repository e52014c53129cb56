"""The pvpython tests' check lines: one printed line per check, failures
remembered for the exit code."""

failures = []


def check(condition, message):
    """Prints one result line and remembers a failure."""
    print(("ok     " if condition else "FAILED ") + message, flush=True)
    if not condition:
        failures.append(message)
    return condition
