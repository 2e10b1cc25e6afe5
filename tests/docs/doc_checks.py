"""What the documentation checks share: how a check reports what it found.

A check script imports it from its own folder (python3 puts the script's folder on sys.path).
"""


def report(problems, failed, passed):
    """Print each problem, then `failed` (if any) or `passed`: the exit status, 1 iff any."""
    for p in problems:
        print(p)
    print(failed if problems else passed)
    return 1 if problems else 0
