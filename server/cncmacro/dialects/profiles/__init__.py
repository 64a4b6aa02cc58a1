"""The built-in control profiles, one module each.

Every module here defines ``PROFILE``, a ``Dialect`` value: its switches and the data module that
holds its tables. ``dialects.registry`` finds them by listing this package, so a new control is a
new module here (and its data and tests), with nothing else to change (docs/profiles.md).
"""
