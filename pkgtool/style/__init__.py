"""ament's style checks (the STY and CPY rules) as plain messages, for packages' linter tests."""
