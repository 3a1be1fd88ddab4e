"""IFC: a package's interface definitions (``.msg``, ``.srv``, ``.action``), read as rosidl
reads them."""
