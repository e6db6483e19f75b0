"""The example case files, shipped inside the package (read by :mod:`runout.validation`).

These files are byte-identical copies of the repository's ``examples/*.toml``, which stay the
user-facing files (README, ``make demo``, the documentation). Edit those, then copy them here::

    cp examples/*.toml src/runout/examples/data/

``tests/cli/test_reproduce_wheel.py`` fails while the two sets differ, and checks that a built
wheel carries these files, so that ``runout reproduce`` works from an installed package and not
only from a source checkout.
"""
