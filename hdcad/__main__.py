from ._entry import leave, run

leave(run())
