"""ENT: console_scripts entry points and the modules and functions they name."""
