"""What every response reports, each defined once: the periodic orbit, the period's metrics (Kv, DTE statistics,
contact loss), spectra, typed metric results and figures.
"""
