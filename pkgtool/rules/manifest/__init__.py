"""MAN: package.xml, checked offline against the REP 127/140/149 schemas and their semantics."""
