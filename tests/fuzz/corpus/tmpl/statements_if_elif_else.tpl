{% if n < 3 %}small{% elif n < 10 %}medium{% elif n < 100 %}large{% else %}huge{% endif %}
{% if n > 100 %}a{% elif n > 50 %}b{% else %}c{% endif %}
{% if n, 0 %}tuple is truthy{% endif %}
{% if [] %}x{% elif {} %}y{% elif '' %}z{% else %}all falsy{% endif %}
%%context
n: 5
