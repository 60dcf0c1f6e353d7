"""The exceptions ede raises. Every message is the library's own: where (file, line, key or byte), what is
wrong, and how to fix it -- the same text the command-line tools print."""


class Error(RuntimeError):
    """Any failure reported by ede's library."""


class InvalidError(Error, ValueError):
    """Bad input: a scene, an argument, a state, or a request outside what the data holds."""


class IoError(Error, OSError):
    """A file could not be opened, read or written."""


class CorruptLogError(Error):
    """A log that is damaged, truncated where it must not be, or not a log at all."""


class UnsupportedError(Error):
    """Valid, but not something this build of ede can do (a newer log version, ...)."""
