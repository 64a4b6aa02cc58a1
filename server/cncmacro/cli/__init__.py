"""The command-line front end: thin adapters from arguments to the analysis and the machine."""
