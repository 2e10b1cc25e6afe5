#!/usr/bin/env python3
"""Run the ```python blocks of a Markdown page in order, in one namespace, as a reader pasting
them would (docs/python.md's worked example). Exit status 1, naming the block, if one raises.

    run_python_doc.py docs/python.md   (any page with ```python blocks)
"""

import re
import sys
import traceback


def main():
    page = sys.argv[1]
    text = open(page, encoding="utf-8").read()
    blocks = re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)
    if not blocks:
        print(f"{page}: no ```python blocks", file=sys.stderr)
        return 1
    namespace = {"__name__": "__doc_example__"}
    for k, block in enumerate(blocks, 1):
        try:
            exec(compile(block, f"{page} (python block {k})", "exec"), namespace)
        except Exception:
            traceback.print_exc()
            print(f"{page}: python block {k} of {len(blocks)} failed", file=sys.stderr)
            return 1
    print(f"{page}: {len(blocks)} python blocks ran")
    return 0


if __name__ == "__main__":
    sys.exit(main())
