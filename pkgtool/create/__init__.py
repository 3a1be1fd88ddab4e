"""``pkgtool create``: options, node kinds, license texts, rendering and the atomic writer."""


class CreateError(Exception):
    """A request ``pkgtool create`` refuses; the message is a full sentence for the user."""
