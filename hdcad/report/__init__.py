"""Results → template context → HTML/PDF. Templates (``templates/``) only format."""
