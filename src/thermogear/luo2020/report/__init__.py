"""The paper's numbers beside thermogear's: :mod:`~thermogear.luo2020.report.values` (each published value with its
source), :mod:`~thermogear.luo2020.report.rows` and :mod:`~thermogear.luo2020.report.checks` (thermogear's value
and its verdict), :mod:`~thermogear.luo2020.report.table` (the table the report and ``reproduce`` print) and
:mod:`~thermogear.luo2020.report.rig_section` (the report's section on the paper's rig)."""
