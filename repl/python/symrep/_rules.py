"""The rule files of an installed package (pip install . or cmake --install; docs/python.md).

An installed package carries the engine's rule files (rules/*.rules of the sources) in
symrep/rules; the engine reads them from $SYMREP_RULES_DIR (engine/rules/rules.h), which this
sets to that folder unless the user set it. The build tree's package has no rules folder: its
module finds the sources' rules/ itself.
"""

import os

_HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "rules")
if os.path.isdir(_HERE):
    os.environ.setdefault("SYMREP_RULES_DIR", _HERE)
