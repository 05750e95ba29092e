"""Errors that the command line turns into a one-line message and exit code 2."""


class InputError(ValueError):
    """Bad user input: a duty file, design option, overlay or model code.

    The message names the field and the allowed range, on one line.
    """

    def __init__(self, field: str, message: str):
        self.field = field
        super().__init__(f"{field}: {message}")
