"""Build, test and grade packages that may hold untrusted code, inside a sandbox.

``sandbox`` runs one command under limits; ``runner`` builds and tests a workspace with it;
``grader`` scores one submission against a ``rubric``; ``batch`` grades many in parallel.
"""
