"""``python -m vorrt ARGS...``: the ``vorrt`` command line, run in-process."""

import sys

from . import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
