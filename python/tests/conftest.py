# SPDX-License-Identifier: GPL-3.0-or-later
# The package is used from the source tree (no install needed): python/ on the path, fixtures
# from robuter.pytest_plugin.
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

pytest_plugins = ["robuter.pytest_plugin"]
