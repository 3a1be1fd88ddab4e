"""``pkgtool add``: grow an existing package (nodes, launch file, parameters, dependencies).

Every change goes through :mod:`pkgtool.edit`: new files are created, existing ones edited in
place with every other byte kept, and nothing is written until the whole operation is known
to succeed.
"""
