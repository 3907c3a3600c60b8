#!/usr/bin/env python3
"""Checks that the Baxter template sets of every target declare the same interface, so that
the same scripts (examples/baxter) compile to all of them.

  baxter_meta_check.py <sim/templates>

For every template of sim/templates/cpp, the template of the same name in each other set
(smach, flexbe) must exist, and their meta blocks must agree on the name, the variables
(name, required or optional, type), input_keys, output_keys and outcomes. Descriptions may
differ: they say what each target's code does. Helper templates of one set only (type None,
e.g. BaxterUtils) are not part of the interface. The check is same_meta_check.py's `baxter`.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import same_meta_check  # noqa: E402


if __name__ == "__main__":
    sys.exit(same_meta_check.main(["baxter"] + sys.argv[1:]))
