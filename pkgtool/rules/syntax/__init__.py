"""SYN: files that cannot be read or parsed."""
