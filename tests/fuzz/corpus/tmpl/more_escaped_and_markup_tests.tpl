{{ 'x' is escaped }} {{ ('x' | e) is escaped }} {{ ('<' | safe) is escaped }} {{ ('a' | e) ~ 'b' }} {{ (('a' | e) + '&') is escaped }}
