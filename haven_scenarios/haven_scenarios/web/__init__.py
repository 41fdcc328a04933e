"""The study in the browser: participant pages, the researcher console, and the door they come through."""
