"""Pure models behind the monitor nodes: simulated sensors and status classification."""
