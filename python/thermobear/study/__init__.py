"""Design studies at scale: a declarative grid over operating conditions
and design variants, computed in chunks (rayon threads inside each native
batch call, or one task per chunk on a Dask cluster), stored as parquet as
the chunks finish, resumed where an earlier run stopped.

>>> import thermobear as tb
>>> s = tb.Study("bearing", {"speed_rpm": [6000, 12000], "axial_n": [300, 600]})
>>> df = s.run(progress=False)
>>> df.height, s.report.computed
(4, 1)

Kinds of point: ``bearing`` (quasi-static solve at speed), ``thermal``
(coupled thermal state of a bearing), ``spindle`` (coupled spindle state),
``gear`` (motion regime at a speed), ``prediction`` (a calibrated model's
outputs at a sample of its calibrated values, ``thermobear.predict.engine``);
[`kinds_table`][thermobear.study.kinds_table] lists every input.
A study can be described in TOML ([`load_study`][thermobear.load_study], ``thermobear study``).
"""

from .config import load_study, parse_study
from .kinds import KINDS, kinds_table
from .study import RunReport, Study

__all__ = ["KINDS", "RunReport", "Study", "kinds_table", "load_study", "parse_study"]
