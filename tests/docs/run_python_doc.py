#!/usr/bin/env python3
"""Run the ```python blocks of a Markdown page in order, in one namespace, as a reader pasting
them would (docs/python.md's worked example). Exit status 1, naming the block, if one raises.

A block whose fence says more than `python` (```python dataset) needs an input the page cannot
give (a dataset on disk): it is left out here and run by its own test, which supplies the input
(docs/python.md's dataset block: tests/python/test_python_doc_dataset.py). python_blocks() is
what both read the page with.

    run_python_doc.py docs/python.md   (any page with ```python blocks)
"""

import re
import sys
import traceback

FENCE = re.compile(r"^```python([^\n]*)\n(.*?)^```", flags=re.S | re.M)


def python_blocks(text):
    """[(info, code)] of a page's ```python blocks in order: the fence's words after `python`
    ('' for a plain block, e.g. 'dataset') and the block's code."""
    return [(m.group(1).strip(), m.group(2)) for m in FENCE.finditer(text)]


def main():
    page = sys.argv[1]
    blocks = python_blocks(open(page, encoding="utf-8").read())
    plain = [code for info, code in blocks if not info]
    if not plain:
        print(f"{page}: no ```python blocks", file=sys.stderr)
        return 1
    namespace = {"__name__": "__doc_example__"}
    for k, block in enumerate(plain, 1):
        try:
            exec(compile(block, f"{page} (python block {k})", "exec"), namespace)
        except Exception:
            traceback.print_exc()
            print(f"{page}: python block {k} of {len(plain)} failed", file=sys.stderr)
            return 1
    others = [info for info, _ in blocks if info]
    print(f"{page}: {len(plain)} python blocks ran"
          + (f"; {len(others)} left to their own tests ({', '.join('python ' + i for i in others)})" if others else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
