"""The conformance survey (defined in `_casteljau_oracle.survey`)."""

from _casteljau_oracle.survey import *  # noqa: F403
from _casteljau_oracle.survey import __doc__  # noqa: F401
