"""The FZG rig of Luo & Li (2020): its measurements (:mod:`~thermogear.luo2020.rig.data`) and the prediction of its
temperatures (:mod:`~thermogear.luo2020.rig.prediction`)."""
