"""The language server (``cncmacro lsp``): a thin pygls front end over the parser, the dialect
tables, the program library and the analysis. Each LSP feature lives in its own module; the
state (open documents, the workspace index, settings) lives on ``CncMacroServer``."""
