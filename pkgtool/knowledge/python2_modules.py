"""Standard library modules of Python 2 that Python 3 renamed or dropped (PEP 3108): the name
code written for Python 2 imports -> what Python 3 has instead."""

from __future__ import annotations

PYTHON2_MODULES: dict[str, str] = {
    "Queue": "queue", "ConfigParser": "configparser", "SocketServer": "socketserver",
    "copy_reg": "copyreg", "repr": "reprlib", "Tkinter": "tkinter",
    "tkMessageBox": "tkinter.messagebox", "tkFileDialog": "tkinter.filedialog",
    "tkSimpleDialog": "tkinter.simpledialog", "tkColorChooser": "tkinter.colorchooser",
    "tkFont": "tkinter.font", "ttk": "tkinter.ttk", "Tix": "tkinter.tix",
    "ScrolledText": "tkinter.scrolledtext", "Tkconstants": "tkinter.constants",
    "urllib2": "urllib.request", "urlparse": "urllib.parse", "robotparser": "urllib.robotparser",
    "httplib": "http.client", "HTMLParser": "html.parser", "htmlentitydefs": "html.entities",
    "Cookie": "http.cookies", "cookielib": "http.cookiejar",
    "BaseHTTPServer": "http.server", "SimpleHTTPServer": "http.server",
    "CGIHTTPServer": "http.server", "xmlrpclib": "xmlrpc.client",
    "SimpleXMLRPCServer": "xmlrpc.server", "DocXMLRPCServer": "xmlrpc.server",
    "cPickle": "pickle", "cStringIO": "io", "StringIO": "io", "UserDict": "collections",
    "UserList": "collections", "UserString": "collections", "__builtin__": "builtins",
    "exceptions": "builtins", "thread": "_thread", "dummy_thread": "_dummy_thread",
    "commands": "subprocess", "popen2": "subprocess", "anydbm": "dbm", "whichdb": "dbm",
    "dumbdbm": "dbm.dumb", "gdbm": "dbm.gnu", "dbhash": "dbm.bsd", "markupbase": "_markupbase",
    "md5": "hashlib", "sha": "hashlib", "sets": "the built-in `set`", "new": "types",
    "mimetools": "email", "rfc822": "email",
}
"""Python 2 module -> its Python 3 replacement (a module, or a phrase in backquotes)."""


def python3_name(module: str) -> str | None:
    """The Python 3 replacement of the Python 2 standard module ``module``, shown for a
    message (``queue``, ``the built-in `set```), or None for any other name."""
    found = PYTHON2_MODULES.get(module)
    return None if found is None else found if found.startswith("the ") else f"`{found}`"
