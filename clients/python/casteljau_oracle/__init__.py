"""The public name of the client: everything is defined in the private package
`_casteljau_oracle` (so that the pytest plugin can load without this name, which a user's
project may have for its own module). See `_casteljau_oracle` for the documentation."""

from _casteljau_oracle import *
from _casteljau_oracle import __all__, __doc__  # noqa: F401
from .prove import prove_identity  # noqa: E402,F401
