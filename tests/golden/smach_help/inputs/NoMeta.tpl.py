{% extends "State.tpl.py" %}
